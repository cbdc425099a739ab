#include "src/stiffness/blocked_force_table.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>

#include "kernels/contact/blocked_force.hpp"
#include "kernels/contact/version.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/progress.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/stiffness/study_strip.hpp"
#include "src/stiffness/table_location.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/stiffness/strip_solves.hpp"

namespace fs = std::filesystem;

namespace rollspec::stiffness {

using namespace study;

namespace {
// Positions per chunk of a path (contact BF-6c): fixed, so the table has the same bits for any
// thread count; 1024 positions make 16 chunks, each starting cold.
constexpr std::size_t kChunkPositions = 64;
// BF-9 (answer_tolerance > 0): one loose path within 5e-2 of the load, moved onto it to first order, and every
// 16th position solved again to the full tolerance, finer while k0's estimated error is above 1e-3 (k0 by
// control variate, F0's error measured there).
constexpr double kAnswerLoadTolerance = 5e-2;
constexpr std::size_t kCheckStride = 16;
constexpr double kCheckK0Tolerance = 1e-3;  // finer checks while k0's estimated error is above it (BF-9a)

const char* kColumns[] = {"position", "force", "stiffness", "psd_wavenumber", "psd"};

std::vector<const std::vector<double>*> columns(const BlockedForceTable& t) {
  return {&t.position, &t.force, &t.stiffness, &t.psd_wavenumber, &t.psd};
}
}  // namespace

const TableKind kBlockedForceTableKind = {kBlockedForceFileType,
                                          "/blocked_force",
                                          "blocked-force-",
                                          "blocked-force table",
                                          {"seed 002", "BF-1..BF-7", "Polonsky-Keer 1999", "D-6", "D-7"}};

std::string BlockedForceTable::checksum() const {
  std::uint64_t h = column_hash(columns(*this));
  for (double v : {approach, k0, mean_force}) h = io::fnv1a64(&v, sizeof v, h);
  // BF-8's columns enter only when present: the exhaustive table's checksum is unchanged.
  if (!force_error.empty()) {
    h = column_hash({&force_error}, h);
    for (double v : {answer_tolerance, load_step}) h = io::fnv1a64(&v, sizeof v, h);
  }
  if (!check_position.empty()) {
    h = column_hash({&check_position, &check_residual}, h);
    h = io::fnv1a64(&k0_error, sizeof k0_error, h);
  }
  return io::hex16(h);
}

double BlockedForceTable::psd_at(double k) const { return path_psd_at(psd_wavenumber, psd, k); }

double BlockedForceTable::band_error_db(double lower, double upper, std::size_t first_bin) const {
  if (position.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  return checked_band_error_db(check_residual, position[1] - position[0], force.size(), psd_wavenumber, psd, lower,
                               upper, first_bin);
}

namespace {

// The grid enters as resolved (derived or set), so the input hash names what was computed.
std::string inputs_text(const TableStudy& ts, const BlockedForceGeometry& g, double radius, double e_star,
                        double load) {
  std::ostringstream in;
  in << ball_inputs_text(ts, radius, e_star, load) << "\n\n[blocked_force]\nstrip_cells = " << g.nx
     << "\nwindow = " << g.window << "\nstep = " << g.step << "\nsegment = " << g.segment
     << "\nchunk_positions = " << kChunkPositions << "\nwarm_start = strip";
  // BF-8 only when chosen: the exhaustive table keeps its inputs (and cache file) of before.
  if (ts.blocked_force.answer_tolerance > 0.0)
    in << "\nanswer_tolerance = " << io::exact_text(ts.blocked_force.answer_tolerance)
       << "\nanswer_load_tolerance = " << io::exact_text(kAnswerLoadTolerance) << "\ncheck_stride = " << kCheckStride
       << "\ncheck_k0_tolerance = " << io::exact_text(kCheckK0Tolerance);
  in << "\nload_tolerance = " << io::exact_text(strip_load_tolerance(ts.stiffness.solver)) << "\nstiffness_tolerance = "
     << io::exact_text(std::max(contact::SolverOptions{}.stiffness_tolerance, ts.stiffness.solver.tolerance)) << "\n";
  in << strip_inputs_text(ts, StripGrid{g.nx, g.ny, g.cell, g.derived_cell});
  return in.str();
}

}  // namespace

void BlockedForceTable::load_from(const io::Hdf5Reader& r) {
  std::vector<std::vector<double>*> cols = {&position, &force, &stiffness, &psd_wavenumber, &psd};
  for (std::size_t i = 0; i < cols.size(); ++i) *cols[i] = r.read(std::string("/blocked_force/") + kColumns[i]);
  approach = r.double_attribute("/blocked_force", "approach");
  k0 = r.double_attribute("/blocked_force", "k0");
  mean_force = r.double_attribute("/blocked_force", "mean_force");
  load = r.double_attribute("/blocked_force", "load");
  if (r.exists("/blocked_force/force_error")) {
    force_error = r.read("/blocked_force/force_error");
    answer_tolerance = r.double_attribute("/blocked_force", "answer_tolerance");
    load_step = r.double_attribute("/blocked_force", "load_step");
  }
  if (r.exists("/blocked_force/check_position")) {
    check_position = r.read("/blocked_force/check_position");
    check_residual = r.read("/blocked_force/check_residual");
    k0_error = r.double_attribute("/blocked_force", "k0_error");
  }
}

BlockedForceTable build_blocked_force(const TableStudy& ts, const BlockedForceGeometry& geo, double radius,
                                      double e_star, double load, bool quiet) {
  const double dx = geo.cell;
  const std::size_t ny = geo.ny, nx = geo.nx, window = geo.window, step = geo.step;
  // One strip realisation (Philox surface streams of realisation 0) from the study's PSD.
  const texture::Surface strip = study_strip(ts, StripGrid{nx, ny, dx, geo.derived_cell}, 0);
  contact::Grid strip_grid{nx, ny, dx, dx}, window_grid{window, window, dx, dx};
  std::vector<double> positions;
  for (std::size_t j = window / 2; j + window / 2 < nx; j += step) positions.push_back(strip_grid.x(j));
  contact::SolverOptions opts = ts.stiffness.solver;
  // The frozen-set stiffness CG to the contact solves' own tolerance (not 1e-12): the table's
  // stiffness cannot be closer than its solves' fields anyway (measured on the seed 002 rig: the
  // stiffness column moves by 2e-8 of its largest value between two runs at 1e-8, with either stop),
  // and it saves a third of the stiffness iterations.
  opts.stiffness_tolerance = std::max(opts.stiffness_tolerance, opts.tolerance);
  const contact::BallShape shape = ts.stiffness.shape;
  if (!quiet)
    std::fprintf(stderr, "%sblocked force grid: %s\n", ensemble::rank_prefix().c_str(), geo.describe().c_str());
  if (!quiet)
    std::fprintf(stderr, "%sblocked force: %zu positions on a %zu x %zu strip\n", ensemble::rank_prefix().c_str(),
                 positions.size(), nx, ny);
  contact::ContactSolver solver(window_grid, e_star);
  contact::BlockedForcePath path;
  try {
    // The search evaluates whole paths until the mean force meets the load: a bar with ETA over each
    // path's positions (each a solve, seconds to a minute on a large strip), then one line per path
    // saying how far its mean force is off the load.
    contact::BlockedForceOptions path_opts;
    path_opts.chunk_positions = kChunkPositions;
    // BF-6 on a rough strip: the contact spots stay on their asperities (measured on the seed 002
    // rig's cold path: 15.4 CG iterations per position against 19.4 with the field shifted with the ball).
    path_opts.warm_start = contact::PathWarmStart::Strip;
    // BF-3 to the solves' own accuracy (as the filter's ER-1): the mean of forces each solved to the
    // solver tolerance cannot be placed on the load more closely; a tighter stop costs a whole path.
    path_opts.load_tolerance = strip_load_tolerance(opts);
    path_opts.answer_tolerance = ts.blocked_force.answer_tolerance;
    path_opts.answer_load_tolerance = kAnswerLoadTolerance;
    path_opts.check_stride = kCheckStride;
    path_opts.check_k0_tolerance = kCheckK0Tolerance;
    int evaluated = 0;
    auto last = std::chrono::steady_clock::now();
    const auto start = last;
    std::clock_t last_cpu = std::clock();
    const std::clock_t start_cpu = last_cpu;
    std::unique_ptr<ensemble::Progress> bar;
    if (!quiet) {
      path_opts.on_chunk = [&](std::size_t done, std::size_t total) {
        if (!bar) {
          bar = std::make_unique<ensemble::Progress>(
              "blocked force path " + std::to_string(evaluated + 1) + " (" + std::to_string(total) + " positions)",
              total, quiet);
          bar->show_after(2.0);
        }
        bar->advance(done);
      };
      path_opts.on_path = [&](const contact::BlockedForcePath& p, double error) {
        if (bar) bar->finish();
        bar.reset();
        const auto now = std::chrono::steady_clock::now();
        const double per = 1.0 / static_cast<double>(std::max(1, p.solves));
        std::fprintf(stderr,
                     "%sblocked force: path %d on %zu positions (%.1f + %.1f CG + stiffness iterations per position, "
                     "%.3g s wall, %.3g s CPU), mean force off the load by %.2e\n",
                     ensemble::rank_prefix().c_str(), ++evaluated, p.position.size(), p.iterations * per,
                     p.stiffness_iterations * per, std::chrono::duration<double>(now - last).count(),
                     static_cast<double>(std::clock() - last_cpu) / CLOCKS_PER_SEC, error);
        last = now;
        last_cpu = std::clock();
      };
    }
    if (!quiet)
      path_opts.on_check = [&](const contact::BlockedForcePath& level, std::size_t stride, double k0_error) {
        const auto now = std::chrono::steady_clock::now();
        std::fprintf(stderr,
                     "%sblocked force: checks at every %zu%s position, %zu of them at the full tolerance (%.1f + %.1f "
                     "CG + stiffness iterations per position, %.3g s wall): k0's estimated error %.2g %%\n",
                     ensemble::rank_prefix().c_str(), stride,
                     stride == 1   ? "st"
                     : stride == 2 ? "nd"
                                   : "th",
                     level.position.size(), level.iterations / std::max(1.0, static_cast<double>(level.solves)),
                     level.stiffness_iterations / std::max(1.0, static_cast<double>(level.solves)),
                     std::chrono::duration<double>(now - last).count(), 100.0 * k0_error);
        last = now;
      };
    path = contact::blocked_force_at_load(solver, strip_grid, strip.heights, radius, shape, positions, load, opts,
                                          path_opts);
    if (!quiet)
      std::fprintf(stderr,
                   "%sblocked force: %d paths (%d on the pre-search subset), %d solves, %.1f + %.1f CG + stiffness "
                   "iterations per solve, %.3g s wall, %.3g s CPU\n",
                   ensemble::rank_prefix().c_str(), path.paths + path.presearch_paths, path.presearch_paths,
                   path.solves, static_cast<double>(path.iterations) / std::max(1, path.solves),
                   static_cast<double>(path.stiffness_iterations) / std::max(1, path.solves),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   static_cast<double>(std::clock() - start_cpu) / CLOCKS_PER_SEC);
    if (!quiet && !path.check_index.empty()) {
      double ss = 0.0;
      for (double r : path.check_residual) ss += r * r;
      std::fprintf(stderr,
                   "%sblocked force: %zu of %zu positions checked at the full tolerance (contact BF-9): k0's estimated "
                   "error %.2g %%, F0's residuals %.3g N rms (F0's mean %.3g N)\n",
                   ensemble::rank_prefix().c_str(), path.check_index.size(), path.position.size(),
                   100.0 * path.k0_error / path.k0, std::sqrt(ss / static_cast<double>(path.check_residual.size())),
                   path.mean_force);
    }
  } catch (const std::invalid_argument& e) {
    ts.blocked_force.origin(ts.blocked_force.window)
        .refuse(std::string(e.what()) + "; widen the window or the strip ([surface] ny)");
  }
  require_converged(path.converged, path.max_error, "blocked force: the path search");
  BlockedForceTable t;
  t.position = path.position;
  t.force = path.force;
  t.stiffness = path.stiffness;
  t.approach = path.approach;
  t.k0 = path.k0;
  t.mean_force = path.mean_force;
  t.load = load;
  t.force_error = path.force_error;
  t.answer_tolerance = ts.blocked_force.answer_tolerance;
  t.load_step = path.load_step;
  for (std::size_t j = 0; j < path.check_index.size(); ++j) {
    t.check_position.push_back(path.position[path.check_index[j]]);
    t.check_residual.push_back(path.check_residual[j]);
  }
  if (!t.check_position.empty()) t.k0_error = path.k0_error;
  f0_psd(t, geo, -1);
  return t;
}

namespace {
// The Welch plan of F0 along the path: f_s = 1 / (step dx) cycles/m, half-overlapping Hann segments.
spectral::WelchConfig f0_welch(const BlockedForceGeometry& g, std::size_t positions) {
  spectral::WelchConfig wc;
  wc.sample_rate = 1.0 / (static_cast<double>(g.step) * g.cell);
  wc.segment = std::min(g.segment, positions);
  wc.overlap = wc.segment / 2;
  return wc;
}
}  // namespace

void f0_psd(BlockedForceTable& t, const BlockedForceGeometry& g, long long skip) {
  const std::size_t n = t.force.size();
  const spectral::WelchPlan plan(f0_welch(g, n));
  spectral::WelchWorkspace ws(plan.config().segment);
  std::vector<double> mean(plan.n_freq(), 0.0);
  if (skip < 0) {
    plan.psd(t.force.data(), n, mean.data(), ws);
  } else {
    // D-30d: the mean of the other segments' periodograms (each segment a Welch estimate of its own:
    // detrended and windowed as in the full average).
    const std::size_t segments = plan.segments(n), hop = plan.config().segment - plan.config().overlap;
    if (static_cast<std::size_t>(skip) >= segments || segments < 2)
      throw std::logic_error("blocked force: no Welch segment to leave out");
    std::vector<double> one(plan.n_freq());
    for (std::size_t j = 0; j < segments; ++j) {
      if (j == static_cast<std::size_t>(skip)) continue;
      plan.psd(t.force.data() + j * hop, plan.config().segment, one.data(), ws);
      for (std::size_t k = 0; k < one.size(); ++k) mean[k] += one[k] / static_cast<double>(segments - 1);
    }
  }
  t.psd_wavenumber.clear();
  t.psd.clear();
  for (std::size_t k = 0; k < mean.size(); ++k) {
    t.psd_wavenumber.push_back(2.0 * M_PI * plan.frequency_step() * static_cast<double>(k));
    t.psd.push_back(mean[k] / (2.0 * M_PI));
  }
}

SegmentJackknife f0_segments(const BlockedForceGeometry& g) {
  const spectral::WelchPlan plan(f0_welch(g, g.positions));
  SegmentJackknife j;
  j.segments = plan.segments(g.positions);
  const double nu = plan.equivalent_dof(g.positions);  // D-16: 2 N / (1 + 2 sum (1 - m/N) rho(m)^2)
  if (j.segments >= 2 && nu > 0.0) {
    j.variance_factor = 2.0 * static_cast<double>(j.segments) / nu;
    j.dof = std::max(1.0, nu / 2.0 - 1.0);
  }
  return j;
}

BlockedForceTable leave_out_segment(const BlockedForceTable& t, std::size_t skip, const BlockedForceGeometry& g) {
  BlockedForceTable s = t;
  f0_psd(s, g, static_cast<long long>(skip));
  return s;
}

void BlockedForceTable::save_to(io::Hdf5Writer& w) const {
  w.write("/blocked_force/position", {position.size()}, position.data(), "m", "ball position along the strip");
  w.write("/blocked_force/force", {force.size()}, force.data(), "N", "blocked force F0 at the fixed approach d0");
  w.write("/blocked_force/stiffness", {stiffness.size()}, stiffness.data(), "N/m",
          "frozen-set stiffness with the sub-cell contact edge along the path (contact README Eq. 11, 13-15)");
  w.write("/blocked_force/psd_wavenumber", {psd_wavenumber.size()}, psd_wavenumber.data(), "rad/m", "wavenumber");
  w.write("/blocked_force/psd", {psd.size()}, psd.data(), "N^2 m/rad", "one-sided PSD of F0 along the path (Welch)");
  w.attribute("/blocked_force", "approach", approach);
  w.attribute("/blocked_force", "k0", k0);
  w.attribute("/blocked_force", "mean_force", mean_force);
  w.attribute("/blocked_force", "load", load);
  if (!force_error.empty()) {
    w.write("/blocked_force/force_error", {force_error.size()}, force_error.data(), "N",
            "estimated error of each F0 (contact BF-8: |step| |k - k_frozen| + solve tolerance |F0|)");
    w.attribute("/blocked_force", "answer_tolerance", answer_tolerance);
    w.attribute("/blocked_force", "load_step", load_step);
  }
  if (!check_position.empty()) {
    w.write("/blocked_force/check_position", {check_position.size()}, check_position.data(), "m",
            "positions solved again to the full tolerance at d0 (contact BF-9)");
    w.write("/blocked_force/check_residual", {check_residual.size()}, check_residual.data(), "N",
            "F0 of the full-tolerance solve there minus the tabulated F0 (contact BF-9b)");
    w.attribute("/blocked_force", "k0_error", k0_error);
  }
}

CachedTable blocked_force_cached_table(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                       double effective_modulus, double load) {
  return CachedTable(kBlockedForceTableKind, ts.store, inputs_text(ts, g, radius, effective_modulus, load));
}

}  // namespace rollspec::stiffness
