#pragma once
// [lines] (scene texture): how many line textures, how long, at what spacing, read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/keyed_section.hpp"

namespace rollspec::study {

class KeyReader;

struct LinesSection : KeyedSection {
  long long count = 10;
  double length = 0.4, spacing = 1e-5;  // m

  static std::vector<KeySpec> keys();
  static LinesSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
