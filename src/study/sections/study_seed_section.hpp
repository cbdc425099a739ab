#pragma once
// [study] seed, read once by the scenes that draw from it. The [study] keys are common to every
// scene and declared with the scene registry (common_keys).
#include <cstdint>

namespace rollspec::study {

class KeyReader;

struct StudySeedSection {
  std::uint64_t seed = 0;

  static StudySeedSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
