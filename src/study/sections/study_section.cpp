#include "src/study/sections/study_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<StudySection> StudySection::declare() {
  using T = StudySection;
  return SectionKeys<T>("study")
      .text("scene", &T::scene, "the scene every realisation runs", std::nullopt)
      .integer("realisations", &T::realisations, "number of Monte-Carlo realisations K", std::nullopt, 1, 1e9)
      .integer("seed", &T::seed, "study seed; realisation i draws from Philox keyed by (seed, i)", std::nullopt, 0,
               9.0e18)
      .text("description", &T::description, "free text describing the study", "");
}
template struct DeclaredSection<StudySection>;

std::string StudySection::seed_setting(std::uint64_t seed) {
  return declared().full_name(&StudySection::seed) + "=" + std::to_string(seed);
}

std::vector<KeySpec> StudySection::keys_with_scenes(const std::vector<std::string>& scenes) {
  std::vector<KeySpec> k = keys();
  for (auto& key : k)
    if (key.full_name() == declared().full_name(&StudySection::scene)) key.type = KeyType::choice, key.choices = scenes;
  return k;
}

}  // namespace rollspec::study
