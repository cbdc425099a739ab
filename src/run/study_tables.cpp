#include "src/run/study_tables.hpp"

#include "src/run/run_phases.hpp"

namespace rollspec::run {

std::vector<StudyTable> study_tables(const study::Study& s, bool force, bool rebuild, bool quiet) {
  check_resources(s, force);
  const auto scene = make_scene<scenes::Scene>(s);
  std::vector<StudyTable> out;
  for (const auto& stage : scene->plan())
    if (stage.table)
      out.push_back(
          {stage.stage, stage.path, (stage.status == scenes::StageStatus::cached ? "cached " : "built ") + stage.path});
  scene->resolve_tables(quiet, rebuild);
  return out;
}

}  // namespace rollspec::run
