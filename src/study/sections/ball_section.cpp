#include "src/study/sections/ball_section.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "kernels/contact/geometry.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> BallSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      real_key("ball", "radius", "m", "ball radius R", std::string("0.02"), 0.0, inf, false),
      real_key("ball", "density", "kg/m^3", "ball density (mass = 4/3 pi R^3 rho)", std::string("7850"), 0.0, inf,
               false),
      real_key("ball", "youngs_modulus", "Pa", "ball Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("ball", "poisson", "-", "ball Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("ball", "speed", "m/s", "rolling speed v", std::string("1"), 0.0, inf, false),
      real_key("ball", "start", "m", "ball position where the record starts", std::string("0.05"), 0.0, inf),
      real_key("ball", "end", "m", "ball position where the record ends", std::string("0.35"), 0.0, inf),
      real_key("ball", "gravity", "m/s^2", "gravitational acceleration", std::string("9.81"), 0.0, inf),
  };
}

BallSection BallSection::parse_solid(const KeyReader& s) {
  BallSection b;
  b.radius = s.real("ball.radius");
  b.density = s.real("ball.density");
  b.youngs_modulus = s.real("ball.youngs_modulus");
  b.poisson = s.real("ball.poisson");
  b.gravity = s.real("ball.gravity");
  return b;
}

BallSection BallSection::parse(const KeyReader& s) {
  BallSection b = parse_solid(s);
  b.speed = s.real("ball.speed");
  b.start = s.real("ball.start");
  b.end = s.real("ball.end");
  b.end_origin = {s.where("ball.end")};
  b.radius_origin = {s.where("ball.radius")};
  b.speed_origin = {s.where("ball.speed")};
  return b;
}

double BallSection::mass() const { return 4.0 / 3.0 * M_PI * radius * radius * radius * density; }

double BallSection::weight() const { return mass() * gravity; }

double BallSection::effective_modulus(double youngs_modulus_other, double poisson_other) const {
  return contact::effective_modulus(youngs_modulus, poisson, youngs_modulus_other, poisson_other);
}

}  // namespace rollspec::study
