#pragma once
// [flat] of scene stiffness: the elastic flat the ball is pressed onto, read once.
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct FlatSection {
  double youngs_modulus = 0.0, poisson = 0.0;

  static FlatSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
