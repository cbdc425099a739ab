#include "src/study/sections/ball_section.hpp"

#include <cmath>

#include "kernels/contact/geometry.hpp"
#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
using B = BallSection;
}  // namespace

SectionKeys<BallSection> BallSection::declare() {
  return SectionKeys<B>("ball")
      .real("radius", &B::radius, "m", "ball radius R", "0.02", above(0.0))
      .real("density", &B::density, "kg/m^3", "ball density (mass = 4/3 pi R^3 rho)", "7850", above(0.0))
      .real("youngs_modulus", &B::youngs_modulus, "Pa", "ball Young's modulus", "210e9", above(0.0))
      .real("poisson", &B::poisson, "-", "ball Poisson's ratio", "0.3", {-1.0, 0.5, false, false})
      .real("speed", &B::speed, "m/s", "rolling speed v", "1", above(0.0))
      .if_present()
      .real("start", &B::start, "m", "ball position where the record starts", "0.05", at_least(0.0))
      .if_present()
      .real("end", &B::end, "m", "ball position where the record ends", "0.35", at_least(0.0))
      .if_present()
      .real("gravity", &B::gravity, "m/s^2", "gravitational acceleration", "9.81", at_least(0.0));
}
template struct DeclaredSection<BallSection>;

std::vector<KeySpec> BallSection::solid_keys() {
  std::vector<KeySpec> k = declared().keys_of(&B::radius, &B::density, &B::youngs_modulus, &B::poisson, &B::gravity);
  k[1].doc = "ball density (weight = 4/3 pi R^3 rho g)";
  k[4].doc += " (for the ball's weight)";
  return k;
}

double BallSection::mass() const { return 4.0 / 3.0 * M_PI * radius * radius * radius * density; }

double BallSection::weight() const { return mass() * gravity; }

double BallSection::effective_modulus(double youngs_modulus_other, double poisson_other) const {
  return contact::effective_modulus(youngs_modulus, poisson, youngs_modulus_other, poisson_other);
}

}  // namespace rollspec::study
