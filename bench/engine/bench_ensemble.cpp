// Ensemble driver throughput: realisations per second with 1 and 2 OpenMP threads on one study,
// measured back to back in one run, and the parallel efficiency. CSV on stdout.
//
//   bench_ensemble [STUDY.ini] [--set section.key=value ...] [--repeat N]
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "src/run/run_phases.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

using namespace rollspec;

int main(int argc, char** argv) {
  std::string study_file = "studies/random-oscillator.ini";
  std::vector<std::string> sets;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--set" && i + 1 < argc)
      sets.emplace_back(argv[++i]);
    else if (a == "--repeat" && i + 1 < argc)
      repeat = std::stoi(argv[++i]);
    else
      study_file = a;
  }
  const study::Study s = study::Study::load(study_file, sets, scenes::schema_for);
  std::printf("study,scene,threads,realisations,best_seconds,realisations_per_second,parallel_efficiency\n");
  double rate1 = 0.0;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto scene = run::make_scene<scenes::EnsembleScene>(s);
    scene->prepare(true, false);
    ensemble::EnsembleConfig cfg;
    cfg.realisations = static_cast<std::uint64_t>(s.integer("study.realisations"));
    cfg.chunk_size = static_cast<std::uint64_t>(s.integer("ensemble.chunk_size"));
    cfg.seed = static_cast<std::uint64_t>(s.integer("study.seed"));
    cfg.quiet = true;
    double best = 1e300;
    for (int r = 0; r < repeat; ++r) {
      const auto sums =
          ensemble::run_ensemble(cfg, scene->values_per_realisation(),
                                 [&](std::uint64_t id, int t, double* v) { scene->run_realisation(id, t, v); });
      best = std::min(best, sums.seconds);
    }
    const double rate = static_cast<double>(cfg.realisations) / best;
    if (threads == 1) rate1 = rate;
    std::printf("%s,%s,%d,%llu,%.4f,%.1f,%.3f\n", study_file.c_str(), s.scene().c_str(), threads,
                static_cast<unsigned long long>(cfg.realisations), best, rate, rate / (rate1 * threads));
  }
  return 0;
}
