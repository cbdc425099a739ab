#pragma once
// [study] (every scene): the scene, the ensemble's size and seed, read once. The keys themselves are the common table
// (scenes/scene_registry); the seed's canonical text is kept for the cached tables' input texts (their hashes).
#include <cstdint>
#include <string>

#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct StudySection {
  std::string scene, description;
  long long realisations = 0;
  std::uint64_t seed = 0;
  std::string seed_text;  // as the resolved study writes it
  KeyOrigin scene_origin;

  static StudySection parse(const KeyReader& s);
};

}  // namespace rollspec::study
