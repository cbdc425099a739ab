#include "src/run/run_loss_effect.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "src/run/run_phases.hpp"
#include "src/ensemble/ensemble_block.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/io/loss_effect.hpp"
#include "src/io/psd_result.hpp"
#include "src/io/run_warning.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/stiffness_section.hpp"

namespace rollspec::run {

void run_loss_effect(const StudyReload& reload, scenes::EnsembleScene& scene, const ensemble::EnsembleConfig& cfg,
                     const ensemble::EnsembleSums& sums, bool quiet, bool rebuild) {
  if (cfg.only >= 0) return;
  // Decided on rank 0 (it holds the sums), known to every rank.
  const std::vector<std::string> sets =
      ensemble::mpi_rank() == 0 ? scene.closed_contact_sets(sums) : std::vector<std::string>{};
  if (!ensemble::any_rank(!sets.empty())) return;
  const std::vector<std::string> closed_sets =
      sets.empty() ? std::vector<std::string>{study::ContactSection::loss_setting(study::ContactLoss::closed),
                                              study::StiffnessSection::table_error_setting(study::TableError::none)}
                   : sets;
  const study::Study closed_study = reload(closed_sets);
  const auto closed = [&closed_study] {
    const io::RunWarningCapture already_said;  // the study's own warnings were said by the run
    return make_scene<scenes::EnsembleScene>(closed_study);
  }();
  closed->prepare(/*quiet=*/true, rebuild);
  const std::size_t nv = scene.values_per_realisation(), lin = scene.linear_spectral_values();
  if (closed->values_per_realisation() != nv) throw std::logic_error("loss effect: closed scene of another shape");
  if (!quiet)
    std::fprintf(stderr,
                 "loss of contact: the realisations again beside the same ones with a contact that never "
                 "opens, to size what it moves\n");
  ensemble::EnsembleConfig c = cfg;
  c.checkpoint_dir.clear();
  c.resume = false;
  c.quiet = quiet;
  const ensemble::EnsembleSums both =
      ensemble::run_ensemble(c, 2 * nv + lin, [&](std::uint64_t id, int thread, double* values) {
        scene.run_realisation(id, thread, values);
        closed->run_realisation(id, thread, values + nv);
        for (std::size_t j = 0; j < lin; ++j) values[2 * nv + j] = values[j] * values[nv + j];
      });
  if (ensemble::mpi_rank() != 0) return;
  const io::PsdEnsemble open = scene.spectra(ensemble::block_sums(both, 0, nv)),
                        shut = closed->spectra(ensemble::block_sums(both, 1, nv));
  const std::size_t n = open.band_scatter.size();
  std::vector<double> products(n);
  for (std::size_t i = 0; i < n; ++i) products[i] = both.sum[2 * nv + lin - n + i];
  scene.include_loss_effect(io::loss_effect(open, shut, products, open.confidence));
}

}  // namespace rollspec::run
