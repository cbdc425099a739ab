#include "src/run/run_table_jackknife.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "src/run/run_phases.hpp"
#include "src/ensemble/ensemble_block.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/io/run_warning.hpp"
#include "src/io/table_error.hpp"

namespace rollspec::run {

namespace {

// After the N runs of realisation `values` filled their blocks: q's summand, sum_i (x_i - mean x)^2,
// for each of the leading `lin` linear values (D-30c), into `q`.
void paired_squares(const double* values, std::size_t n, std::size_t nv, std::size_t lin, double* q) {
  for (std::size_t j = 0; j < lin; ++j) {
    double mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) mean += values[i * nv + j];
    mean /= static_cast<double>(n);
    double sq = 0.0;
    for (std::size_t i = 0; i < n; ++i) sq += (values[i * nv + j] - mean) * (values[i * nv + j] - mean);
    q[j] = sq;
  }
}
}  // namespace

namespace {

// D-30f: the sub-table runs' own noise n (D-30c) falls as 1/K_J, the table's part V_J - n does not; the
// sub-table ensemble is run again with K_J raised until n is at most a quarter of the table's part
// (median over the bands), up to kJackknifeRealisationFactor K and kJackknifeRealisationCap realisations:
// the term's cost stays a bounded multiple of the run's (a 5-realisation look at a study does not run
// thousands), and where the cap stops it the run warns with what would be needed.
constexpr std::uint64_t kJackknifeRealisationCap = 1024;
constexpr std::uint64_t kJackknifeRealisationFactor = 8;
constexpr double kNoiseShareTarget = 0.25;

// The sub-tables' ensemble of k realisations (ids 0..k-1 of the study's streams): the jackknife and its noise.
struct JackknifePass {
  io::TableError table;
  std::uint64_t realisations = 0;
};

}  // namespace

void run_table_jackknife(const study::Study& s, const StudyReload& reload, scenes::EnsembleScene& scene,
                         const ensemble::EnsembleConfig& cfg, bool quiet, bool rebuild) {
  if (!scene.estimates_table_error() || cfg.only >= 0) return;
  (void)s;
  const scenes::TableJackknifePlan plan = scene.table_jackknife();
  const std::size_t n = plan.n;
  std::vector<std::unique_ptr<scenes::EnsembleScene>> subs;
  for (std::size_t i = 0; i < n; ++i) {
    const study::Study sub = reload(plan.leave_out_sets(static_cast<long long>(i)));
    subs.push_back([&sub] {
      // The full table's study again: its construction warnings were said once, by the full run.
      const io::RunWarningCapture already_said;
      return make_scene<scenes::EnsembleScene>(sub);
    }());
    subs.back()->prepare(/*quiet=*/true, rebuild);  // its table is cached, or reduced from the full one
  }
  const std::size_t nv = scene.values_per_realisation(), lin = scene.linear_spectral_values();
  for (const auto& sub : subs)
    if (sub->values_per_realisation() != nv)
      throw std::logic_error("table jackknife: sub-table scene of another shape");
  // One ensemble whose realisation runs the N sub-tables' scenes on the same streams (common random
  // numbers), so that the same realisation's values can be paired across them (D-30c).
  const auto pass = [&](std::uint64_t k) {
    if (!quiet)
      std::fprintf(stderr,
                   "table jackknife: %llu realisations again with each of the %zu sub-tables of the %s (one of its "
                   "%s left out of each), realisation by realisation\n",
                   static_cast<unsigned long long>(k), n, plan.table.c_str(), plan.unit.c_str());
    ensemble::EnsembleConfig c = cfg;
    c.realisations = k;
    c.checkpoint_dir.clear();
    c.resume = false;
    c.quiet = quiet;
    const ensemble::EnsembleSums sums =
        ensemble::run_ensemble(c, n * nv + lin, [&](std::uint64_t id, int thread, double* values) {
          for (std::size_t i = 0; i < n; ++i) subs[i]->run_realisation(id, thread, values + i * nv);
          paired_squares(values, n, nv, lin, values + n * nv);
        });
    JackknifePass out;
    out.realisations = k;
    if (ensemble::mpi_rank() != 0) return out;
    std::vector<io::PsdEnsemble> spectra;
    io::PairedSums paired;
    paired.realisations = sums.count;
    paired.q.assign(sums.sum.begin() + static_cast<std::ptrdiff_t>(n * nv), sums.sum.end());
    for (std::size_t i = 0; i < n; ++i) {
      const ensemble::EnsembleSums b = ensemble::block_sums(sums, i, nv);
      spectra.push_back(subs[i]->spectra(b));
      std::vector<double> m(lin);
      for (std::size_t j = 0; j < lin; ++j) m[j] = b.mean(j);
      paired.means.push_back(std::move(m));
    }
    out.table = io::table_jackknife(spectra, paired, plan.table, plan.unit, plan.variance_factor, plan.dof);
    return out;
  };
  JackknifePass j = pass(cfg.realisations);
  // D-30f: enough realisations that the runs' own noise is a small part of the term. Decided on rank 0,
  // known to every rank (the others add 0).
  std::uint64_t wanted = 0, needed = 0;
  if (ensemble::mpi_rank() == 0) {
    const double ratio = io::median_noise_ratio(j.table);  // n / (V_J - n)
    if (ratio > kNoiseShareTarget) {
      const double k = std::ceil(static_cast<double>(cfg.realisations) * ratio / kNoiseShareTarget);
      needed = std::isfinite(k) && k < 1e15 ? static_cast<std::uint64_t>(k) : 0;
      const std::uint64_t cap = std::max(
          cfg.realisations, std::min(kJackknifeRealisationCap, kJackknifeRealisationFactor * cfg.realisations));
      wanted = std::min<std::uint64_t>(needed == 0 ? cap : needed, cap);
    }
  }
  wanted = ensemble::sum_over_ranks(wanted);
  if (wanted > cfg.realisations) j = pass(wanted);
  if (ensemble::mpi_rank() != 0) return;
  io::TableError& t = j.table;
  t.independent_bands = plan.independent_bands;
  t.realisations = j.realisations;
  t.noise_warning = io::table_noise_warning(t, j.realisations);
  if (!t.noise_warning.empty() && wanted > 0 && (needed == 0 || needed > wanted))
    t.noise_warning += " (the sub-table runs stopped at their cap of " + std::to_string(wanted) +
                       " realisations, 8 K and at most 1024" +
                       (needed > wanted ? "; about " + std::to_string(needed) + " would make it trustworthy" : "") +
                       "; kernels/spectral D-30f)";
  if (!t.noise_warning.empty()) io::warn(t.noise_warning, true);  // the result's validity, not progress
  scene.include_table_error(std::move(t));
}

}  // namespace rollspec::run
