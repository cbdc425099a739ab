#pragma once
// [ball] of scene ball-on-beam: the rigid ball and its traverse, read once. Its weight and the
// contact modulus E* against the beam are derived here only (the scene, the table stages and the
// memory estimate all use these).
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct BallSection : DeclaredSection<BallSection> {
  double radius = 0.0, density = 0.0, youngs_modulus = 0.0, poisson = 0.0;
  double speed = 0.0, start = 0.0, end = 0.0, gravity = 0.0;

  // The ball alone (radius, density, elastic constants, gravity): scene stiffness's [ball], which has no
  // traverse, its docs naming the weight.
  static std::vector<KeySpec> solid_keys();
  // The traverse (speed, start, end) is read where the scene has it.
  static SectionKeys<BallSection> declare();
  double mass() const;    // 4/3 pi R^3 rho
  double weight() const;  // mass x gravity
  // E* of the ball on a body of modulus E and Poisson's ratio nu (kernels/contact geometry).
  double effective_modulus(double youngs_modulus_other, double poisson_other) const;
};

}  // namespace rollspec::study
