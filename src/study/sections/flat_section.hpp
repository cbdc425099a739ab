#pragma once
// [flat] of scene stiffness: the elastic flat the ball is pressed onto, read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/keyed_section.hpp"

namespace rollspec::study {

class KeyReader;

struct FlatSection : KeyedSection {
  double youngs_modulus = 0.0, poisson = 0.0;

  static std::vector<KeySpec> keys();
  static FlatSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
