#include "src/cli/run_table_jackknife.hpp"

#include <cstdio>
#include <vector>

#include "src/cli/run_phases.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/io/run_warning.hpp"
#include "src/io/table_error.hpp"
#include "src/study/sections/stiffness_section.hpp"

namespace rollspec::cli {

void run_table_jackknife(const study::Study& s, const StudyReload& reload, scenes::EnsembleScene& scene,
                         const ensemble::EnsembleConfig& cfg, bool quiet, bool rebuild) {
  if (!study::StiffnessSection::asks_table_jackknife(s) || cfg.only >= 0) return;
  const study::StiffnessSection stiffness = study::StiffnessSection::parse(s);
  const long long n = stiffness.realisations;
  std::vector<io::PsdEnsemble> subs;
  for (long long i = 0; i < n; ++i) {
    if (!quiet)
      std::fprintf(stderr, "table jackknife: the ensemble with sub-table %lld of %lld (surface %lld left out)\n", i + 1,
                   n, i);
    const study::Study sub = reload(study::StiffnessSection::leave_out_sets(i));
    const auto sub_scene = [&sub] {
      // The full table's study again: its construction warnings were said once, by the full run.
      const io::RunWarningCapture already_said;
      return make_scene<scenes::EnsembleScene>(sub);
    }();
    sub_scene->prepare(/*quiet=*/true, rebuild);  // its table is cached: the full table's scene built it
    ensemble::EnsembleConfig c = cfg;
    c.checkpoint_dir.clear();
    c.resume = false;
    c.quiet = quiet;
    c.study_hash = scenes::study_result_hash(sub);
    const ensemble::EnsembleSums sums = ensemble::run_ensemble(
        c, sub_scene->values_per_realisation(),
        [&](std::uint64_t id, int thread, double* values) { sub_scene->run_realisation(id, thread, values); });
    if (ensemble::mpi_rank() == 0) subs.push_back(sub_scene->spectra(sums));
  }
  if (ensemble::mpi_rank() == 0) scene.include_table_error(io::table_jackknife(subs, "stiffness table"));
}

}  // namespace rollspec::cli
