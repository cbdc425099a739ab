#pragma once
// [study]: the scene and the seed, read once (the keys themselves are every scene's common table).
#include <cstdint>
#include <string>

#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct StudySection {
  std::string scene;
  std::uint64_t seed = 0;
  KeyOrigin scene_origin;

  static StudySection parse(const KeyReader& s);
};

}  // namespace rollspec::study
