#pragma once
// [output] (scene ball-on-beam): stored time histories and the linearised law's reference, read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct OutputSection : DeclaredSection<OutputSection> {
  long long time_histories = 0;
  bool reference = true;

  static SectionKeys<OutputSection> declare();
};

}  // namespace rollspec::study
