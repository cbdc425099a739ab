#include "src/scenes/texture/texture_scene.hpp"

#include "src/error.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/lines_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> texture_scene_keys() {
  return joined_keys(
      {TextureSection::keys(), LinesSection::keys(), SurfaceSection::keys(), SurfaceSection::count_keys()});
}

namespace {
class TextureScene final : public Scene {
 public:
  explicit TextureScene(const KeyReader& s)
      : lines_(LinesSection::parse(s).count), surfaces_(SurfaceSection::parse(s).count) {
    texture_io::study_psd(TextureSection::parse(s));  // validates the PSD source (files, ranges) now
    add_stages(fixed_stages());                       // after the members the descriptions name
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

// The line spacing is set against the default short cut-off (the key's default is too coarse for it).
std::vector<FirstKey> texture_first_keys() {
  return {first_key(&TextureSection::source),
          first_key(&TextureSection::rms),
          first_key(&TextureSection::hurst),
          first_key(&TextureSection::rolloff_wavelength),
          first_key(&TextureSection::short_wavelength),
          first_key(&LinesSection::count),
          first_key(&LinesSection::length),
          first_key(&LinesSection::spacing, "5e-6"),
          first_key(&SurfaceSection::count)};
}

}  // namespace rollspec::scenes
