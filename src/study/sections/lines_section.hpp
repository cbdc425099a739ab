#pragma once
// [lines] (scene texture): how many line textures, how long, at what spacing, read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct LinesSection : DeclaredSection<LinesSection> {
  long long count = 10;
  double length = 0.4, spacing = 1e-5;  // m

  static SectionKeys<LinesSection> declare();
};

}  // namespace rollspec::study
