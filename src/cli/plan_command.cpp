// rollspec plan: which stages a study runs, reuses from cache, or skips, and why.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <vector>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/cli/plan_tables.hpp"
#include "src/run/run_phases.hpp"
#include "src/cli/sweep_options.hpp"
#include "src/cli/sweep_plan.hpp"
#include "src/run/sweep_run.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/io/available_memory.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

using run::kDefaultMaxSweepPoints;
using run::load_sweep;
using run::make_scene;
using run::resolve_study;

int plan_command(const Args& args) {
  const std::string usage =
      "usage: rollspec plan STUDY.ini [--set section.key=value ...] [--sweep section.key=v1,v2,...]\n"
      "\n"
      "Validates the study and prints each stage of its scene as run / cached / skipped with the\n"
      "reason, and the estimated peak memory and checkpoint disk. Nothing is computed and no file is\n"
      "written. A table that is not built yet and whose cost depends on the texture (the equivalent\n"
      "roughness of filter = solver) has its first solves timed to estimate its build, when they take a\n"
      "few seconds. --probe runs realisation 0 once (when the stage tables exist) to estimate the run\n"
      "time, and times those solves whatever they take.";
  po::options_description opts("options");
  opts.add_options()("probe",
                     "run realisation 0 once to estimate the run time (and time the first solves of a missing "
                     "equivalent-roughness table however long they take)");
  StudyArgs study;
  po::positional_options_description pos;
  add_study_options(opts, pos, study);
  std::vector<std::string> sweeps;
  std::size_t max_points = kDefaultMaxSweepPoints;
  add_sweep_option(opts, sweeps, max_points);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (const auto sweep = load_sweep(study, sweeps, {max_points, false, false}))
    return plan_sweep(*sweep, vm.count("probe") > 0);

  const study::Study s = resolve_study(study);
  const study::StudySection study_keys = study::StudySection::parse(s);
  std::cout << "study " << study.file << ": scene " << s.scene() << ", "
            << io::counted(static_cast<unsigned long long>(study_keys.realisations), "realisation") << ", seed "
            << study_keys.seed << "\n";
  const int threads = ensemble::ensemble_threads();
  const auto memory = scenes::estimate_memory(s, threads);
  const double available = io::available_memory();
  std::string keys;
  for (const auto& k : memory.keys) keys += (keys.empty() ? "" : ", ") + k;
  std::cout << "memory: estimated peak " << scenes::format_bytes(memory.bytes) << " on " << threads << " thread"
            << (threads == 1 ? "" : "s")
            << (memory.what.empty() ? std::string() : " (largest: " + memory.what + ", from " + keys + ")")
            << "; available " << scenes::format_bytes(available) << "\n";
  for (const auto& [what, bytes] : memory.terms)
    std::cout << "  " << scenes::format_bytes(bytes) << ": " << what << "\n";
  if (memory.bytes > available) {
    std::cout << "the study needs more memory than is available: rollspec run refuses it (unless --force); stages not "
                 "shown\n";
    return 0;
  }
  const auto scene = make_scene<scenes::Scene>(s);
  auto* ensemble_scene = dynamic_cast<scenes::EnsembleScene*>(scene.get());
  if (ensemble_scene) {
    const double K = static_cast<double>(study_keys.realisations),
                 C = static_cast<double>(study::EnsembleSection::parse(s).chunk_size);
    const double chunk_bytes = 48.0 + 16.0 * static_cast<double>(ensemble_scene->values_per_realisation());
    std::cout << "checkpoint disk: " << io::counted(static_cast<unsigned long long>(std::ceil(K / C)), "chunk")
              << " of " << scenes::format_bytes(chunk_bytes) << " = "
              << scenes::format_bytes(std::ceil(K / C) * chunk_bytes) << " beside the result while the run lasts\n";
  }
  for (const auto& w : scene->warnings()) std::cout << "warning: " << w << "\n";
  if (const std::string note = texture_io::profile_note(study::TextureSection::parse(s)); !note.empty())
    std::cout << "note: " << note << "\n";
  std::printf("%-16s %-8s %s\n", "stage", "status", "reason");
  const auto stages = scene->plan();
  for (const auto& p : stages)
    std::printf("%-16s %-8s %s\n", p.stage.c_str(), scenes::status_name(p.status), p.reason.c_str());
  const bool tables_missing = any_missing_table(stages);
  // The table's own error (D-30, D-30f): the ensemble once with the table and once per sub-table.
  const bool jackknife = ensemble_scene && ensemble_scene->estimates_table_error();
  const scenes::TableJackknifePlan jk = jackknife ? ensemble_scene->table_jackknife() : scenes::TableJackknifePlan{};
  const double ensembles = static_cast<double>(jk.n) + 1.0;
  if (jackknife) {
    std::printf(
        "table jackknife: the %s's own error ([stiffness] table_error) runs the ensemble %zu times (the full table and "
        "each of its %zu leave-one-out sub-tables, the same realisation streams): %zu x the ensemble's run time, more "
        "where the sub-table runs' own noise asks for up to %d realisations each (kernels/spectral D-30f); the "
        "sub-tables %s\n",
        jk.table.c_str(), jk.n + 1, jk.n, jk.n + 1, 1024,
        jk.unit == "surfaces" ? "are cached, made from one more solve of each surface when missing"
                              : ("are made from the full table's " + jk.unit + ", without a new solve").c_str());
  }
  // The tables it would build whose cost the plan's model misses: measured on a few of their solves
  // (without --probe only when that is quick).
  const bool probing = vm.count("probe") > 0;
  if (ensemble_scene)
    for (const auto& t : ensemble_scene->probe_tables(table_probe_limit(probing)))
      std::cout << table_probe_line(t) << "\n";
  if (!probing) return 0;
  if (!ensemble_scene) {
    std::cout << "run time: not probed (no ensemble: the run is one deterministic computation)\n";
    return 0;
  }
  if (tables_missing) {
    std::cout << "run time: not probed (the stage tables are not built yet; rollspec run builds them, rollspec "
                 "stiffness the stiffness table alone)\n";
    return 0;
  }
  // The tables are cached: this loads them. The probe runs the full table alone: no sub-table is built.
  std::unique_ptr<scenes::EnsembleScene> plain;
  if (jackknife) {
    StudyArgs without = study;
    without.sets.push_back(study::StiffnessSection::table_error_setting(study::TableError::none));
    plain = make_scene<scenes::EnsembleScene>(resolve_study(without));
  }
  scenes::EnsembleScene& probe = plain ? *plain : *ensemble_scene;
  probe.prepare(true, false);
  std::vector<double> values(probe.values_per_realisation());
  const auto start = std::chrono::steady_clock::now();
  probe.run_realisation(0, 0, values.data());
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double K = static_cast<double>(study_keys.realisations);
  std::printf(
      "run time: %.3g s per realisation (probe of realisation 0); the ensemble of %.0f on %d thread(s): about %.3g s "
      "(plus stage tables and the final write)\n",
      t, K, threads, t * K / threads);
  if (jackknife)
    std::printf("run time with the table jackknife: %.0f ensembles, about %.3g s\n", ensembles,
                ensembles * t * K / threads);
  return 0;
}

}  // namespace rollspec::cli
