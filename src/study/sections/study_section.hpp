#pragma once
// [study] (every scene): the scene, the ensemble's size and seed, read once. Its keys open the common table of
// every scene (scenes/scene_registry), the scene's allowed values the registry's names (scene_key).
#include <cstdint>
#include <string>
#include <vector>

#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

struct StudySection : DeclaredSection<StudySection> {
  std::string scene, description;
  long long realisations = 0;
  std::uint64_t seed = 0;

  static SectionKeys<StudySection> declare();
  // keys() with `scene` a choice of `scenes` (the registry's names, which this layer does not know).
  static std::vector<KeySpec> keys_with_scenes(const std::vector<std::string>& scenes);
  static std::string seed_setting(std::uint64_t seed);  // "study.seed=<seed>", a --set text
};

}  // namespace rollspec::study
