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
#include "src/run/study_plan.hpp"
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
  StudyCommandOptions cl;
  cl.options.add_options()("probe",
                           "run realisation 0 once to estimate the run time (and time the first solves of a missing "
                           "equivalent-roughness table however long they take)");
  std::vector<std::string> sweeps;
  std::size_t max_points = kDefaultMaxSweepPoints;
  add_sweep_option(cl.options, sweeps, max_points);
  if (!cl.parse(args, usage)) return 0;
  if (const auto sweep = load_sweep(cl.study, sweeps, {max_points, false, false}))
    return plan_sweep(*sweep, cl.vm.count("probe") > 0);

  const bool probing = cl.vm.count("probe") > 0;
  const run::StudyPlan p = run::plan_study(cl.study, probing);
  std::cout << "study " << cl.study.file << ": scene " << p.scene << ", "
            << io::counted(static_cast<unsigned long long>(p.realisations), "realisation") << ", seed " << p.seed
            << "\n";
  const auto& memory = p.memory;
  std::string keys;
  for (const auto& k : memory.keys) keys += (keys.empty() ? "" : ", ") + k;
  std::cout << "memory: estimated peak " << scenes::format_bytes(memory.bytes) << " on " << p.threads << " thread"
            << (p.threads == 1 ? "" : "s")
            << (memory.what.empty() ? std::string() : " (largest: " + memory.what + ", from " + keys + ")")
            << "; available " << scenes::format_bytes(p.available_bytes) << "\n";
  for (const auto& [what, bytes] : memory.terms)
    std::cout << "  " << scenes::format_bytes(bytes) << ": " << what << "\n";
  if (p.over_memory) {
    std::cout << "the study needs more memory than is available: rollspec run refuses it (unless --force); stages not "
                 "shown\n";
    return 0;
  }
  if (p.ensemble)
    std::cout << "checkpoint disk: " << io::counted(p.chunks, "chunk") << " of " << scenes::format_bytes(p.chunk_bytes)
              << " = " << scenes::format_bytes(static_cast<double>(p.chunks) * p.chunk_bytes)
              << " beside the result while the run lasts\n";
  for (const auto& w : p.warnings) std::cout << "warning: " << w << "\n";
  if (!p.note.empty()) std::cout << "note: " << p.note << "\n";
  std::printf("%-16s %-8s %s\n", "stage", "status", "reason");
  for (const auto& s : p.stages)
    std::printf("%-16s %-8s %s\n", s.stage.c_str(), scenes::status_name(s.status), s.reason.c_str());
  // The table's own error (D-30, D-30f): the ensemble once with the table and once per sub-table.
  const auto& jk = p.jk;
  const double ensembles = static_cast<double>(jk.n) + 1.0;
  if (p.jackknife) {
    std::printf(
        "table jackknife: the %s's own error ([stiffness] table_error) runs the ensemble %zu times (the full table and "
        "each of its %zu leave-one-out sub-tables, the same realisation streams): %zu x the ensemble's run time, more "
        "where the sub-table runs' own noise asks for up to %d realisations each (kernels/spectral D-30f); the "
        "sub-tables %s\n",
        jk.table.c_str(), jk.n + 1, jk.n, jk.n + 1, 1024,
        jk.unit == "surfaces" ? "are cached, made from one more solve of each surface when missing"
                              : ("are made from the full table's " + jk.unit + ", without a new solve").c_str());
  }
  for (const auto& t : p.tables) std::cout << table_probe_line(t) << "\n";
  if (!probing) return 0;
  if (!p.seconds_per_realisation) {
    std::cout << "run time: not probed (" << p.not_probed << ")\n";
    return 0;
  }
  const double t = *p.seconds_per_realisation;
  std::printf(
      "run time: %.3g s per realisation (probe of realisation 0); the ensemble of %.0f on %d thread(s): about %.3g s "
      "(plus stage tables and the final write)\n",
      t, static_cast<double>(p.realisations), p.threads, p.ensemble_seconds());
  if (p.jackknife)
    std::printf("run time with the table jackknife: %.0f ensembles, about %.3g s\n", ensembles,
                ensembles * p.ensemble_seconds());
  return 0;
}

}  // namespace rollspec::cli
