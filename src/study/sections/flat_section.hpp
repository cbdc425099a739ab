#pragma once
// [flat] of scene stiffness: the elastic flat the ball is pressed onto, read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct FlatSection : DeclaredSection<FlatSection> {
  double youngs_modulus = 0.0, poisson = 0.0;

  static SectionKeys<FlatSection> declare();
};

}  // namespace rollspec::study
