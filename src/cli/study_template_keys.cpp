#include "src/cli/study_template_keys.hpp"

#include "src/scenes/scene.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::cli {

std::vector<FirstKey> first_keys(const std::string& scene) {
  using study::StudySection;
  std::vector<FirstKey> keys = {
      scenes::first_key(&StudySection::scene, scene),
      scenes::first_key(&StudySection::description, scene + " study written by rollspec init"),
      scenes::first_key(&StudySection::realisations, "100"),
      scenes::first_key(&StudySection::seed, "1"),
  };
  const auto& rig = scenes::find_scene(scene).first_keys;
  keys.insert(keys.end(), rig.begin(), rig.end());
  return keys;
}

}  // namespace rollspec::cli
