#include "src/scenes/texture_scene.hpp"

#include <limits>

#include "src/error.hpp"
#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> texture_scene_keys() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<KeySpec> keys = texture_io::psd_keys();
  keys.push_back(integer_key("lines", "count", "line textures to generate", std::string("10"), 0, 1e6));
  keys.push_back(real_key("lines", "length", "m", "length of each line texture", std::string("0.4"), 0.0, inf, false));
  keys.push_back(real_key("lines", "spacing", "m", "sample spacing dx of the lines (dx <= pi / k_max)",
                          std::string("1e-5"), 0.0, inf, false));
  for (auto& k : texture_io::surface_keys()) keys.push_back(k);
  keys.push_back(integer_key("surface", "count", "isotropic surfaces to generate", std::string("0"), 0, 1e6));
  return keys;
}

namespace {
class TextureScene final : public Scene {
 public:
  explicit TextureScene(const KeyReader& s) : lines_(s.integer("lines.count")), surfaces_(s.integer("surface.count")) {
    texture_io::study_psd(s);    // validates the PSD source (files, ranges) now
    add_stages(fixed_stages());  // after the members the descriptions name
  }
  std::vector<StagePlan> fixed_stages() const {
    return {
        {"texture", lines_ ? StageStatus::run : StageStatus::skipped,
         lines_ ? std::to_string(lines_) + " line textures from [texture] ([lines])" : "[lines] count = 0"},
        {"surface", surfaces_ ? StageStatus::run : StageStatus::skipped,
         surfaces_ ? std::to_string(surfaces_) + " isotropic surfaces ([surface])" : "[surface] count = 0"},
        {"stiffness_table", StageStatus::skipped, "the scene has no contact"},
        {"dynamics", StageStatus::skipped, "the scene has no dynamics"},
        {"spectra", StageStatus::skipped, "the scene has no sensors"},
    };
  }

 private:
  long long lines_, surfaces_;
};
}  // namespace

std::unique_ptr<Scene> make_texture_scene(const KeyReader& s) { return std::make_unique<TextureScene>(s); }

}  // namespace rollspec::scenes
