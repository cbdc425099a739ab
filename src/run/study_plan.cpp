#include "src/run/study_plan.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "src/ensemble/ensemble_driver.hpp"
#include "src/io/available_memory.hpp"
#include "src/run/run_phases.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"

namespace rollspec::run {

bool missing_table(const scenes::StagePlan& stage) { return stage.status == scenes::StageStatus::run && stage.table; }

bool any_missing_table(const std::vector<scenes::StagePlan>& stages) {
  for (const auto& p : stages)
    if (missing_table(p)) return true;
  return false;
}

double table_probe_limit(bool probe) {
  return probe ? std::numeric_limits<double>::infinity() : stiffness::kQuickProbeSeconds;
}

StudyPlan plan_study(const StudyArgs& args, bool probe) {
  const study::Study s = resolve_study(args);
  const study::StudySection study_keys = study::StudySection::parse(s);
  StudyPlan p;
  p.file = args.file, p.scene = s.scene();
  p.realisations = static_cast<long long>(study_keys.realisations);
  p.seed = static_cast<unsigned long long>(study_keys.seed);
  p.threads = ensemble::ensemble_threads();
  p.memory = scenes::estimate_memory(s, p.threads);
  p.available_bytes = io::available_memory();
  if (p.memory.bytes > p.available_bytes) {
    p.over_memory = true;
    return p;
  }
  const auto scene = make_scene<scenes::Scene>(s);
  auto* ensemble_scene = dynamic_cast<scenes::EnsembleScene*>(scene.get());
  p.ensemble = ensemble_scene != nullptr;
  if (ensemble_scene) {
    const double K = static_cast<double>(study_keys.realisations),
                 C = static_cast<double>(study::EnsembleSection::parse(s).chunk_size);
    p.chunks = static_cast<unsigned long long>(std::ceil(K / C));
    p.chunk_bytes = 48.0 + 16.0 * static_cast<double>(ensemble_scene->values_per_realisation());
  }
  p.warnings = scene->warnings();
  p.note = texture_io::profile_note(study::TextureSection::parse(s));
  p.stages = scene->plan();
  p.jackknife = ensemble_scene && ensemble_scene->estimates_table_error();
  if (p.jackknife) p.jk = ensemble_scene->table_jackknife();
  // The tables it would build whose cost the plan's model misses: measured on a few of their solves
  // (without a probe only when that is quick).
  if (ensemble_scene) p.tables = ensemble_scene->probe_tables(table_probe_limit(probe));
  if (!probe) return p;
  if (!ensemble_scene) {
    p.not_probed = "no ensemble: the run is one deterministic computation";
    return p;
  }
  if (any_missing_table(p.stages)) {
    p.not_probed =
        "the stage tables are not built yet; rollspec run builds them, rollspec stiffness the stiffness table alone";
    return p;
  }
  // The tables are cached: this loads them. The probe runs the full table alone: no sub-table is built.
  std::unique_ptr<scenes::EnsembleScene> plain;
  if (p.jackknife) {
    StudyArgs without = args;
    without.sets.push_back(study::StiffnessSection::table_error_setting(study::TableError::none));
    plain = make_scene<scenes::EnsembleScene>(resolve_study(without));
  }
  scenes::EnsembleScene& run = plain ? *plain : *ensemble_scene;
  run.prepare(true, false);
  std::vector<double> values(run.values_per_realisation());
  const auto start = std::chrono::steady_clock::now();
  run.run_realisation(0, 0, values.data());
  p.seconds_per_realisation = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

}  // namespace rollspec::run
