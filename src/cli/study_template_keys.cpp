#include "src/cli/study_template_keys.hpp"

#include "src/scenes/scene.hpp"

namespace rollspec::cli {

std::vector<FirstKey> first_keys(const std::string& scene) {
  std::vector<FirstKey> keys = {
      {"study.scene", scene},
      {"study.description", scene + " study written by rollspec init"},
      {"study.realisations", "100"},
      {"study.seed", "1"},
  };
  const auto& rig = scenes::find_scene(scene).first_keys;
  keys.insert(keys.end(), rig.begin(), rig.end());
  return keys;
}

}  // namespace rollspec::cli
