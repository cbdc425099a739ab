#include "src/run/study_stiffness_table.hpp"

#include "src/run/run_phases.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::run {

StudyStiffnessTable study_stiffness_table(const study::Study& s, bool force, bool rebuild, bool quiet) {
  const auto has_table = [](const scenes::SceneInfo& i) { return static_cast<bool>(i.contact_pair); };
  const scenes::SceneInfo& scene = scenes::find_scene(s.scene());
  if (!has_table(scene)) {
    const auto study_keys = study::StudySection::parse(s);
    study_keys.origin(study_keys.scene)
        .refuse("rollspec stiffness needs a " + scenes::scenes_with(has_table) + " study");
  }
  check_resources(s, force);
  StudyStiffnessTable answer;
  answer.pair = scene.contact_pair(s);
  const stiffness::TableStudy ts = stiffness::TableStudy::parse(s);
  answer.table =
      stiffness::resolve_table(ts, answer.pair.radius, answer.pair.effective_modulus, rebuild, quiet, answer.status);
  answer.path = stiffness::stiffness_cached_table(ts, answer.pair.radius, answer.pair.effective_modulus).path();
  return answer;
}

}  // namespace rollspec::run
