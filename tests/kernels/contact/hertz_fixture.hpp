#pragma once
// Smooth paraboloid on a flat: the continuum Hertz solution is exact for this gap (kernels/README.md (contact)).
#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"

namespace rollspec::contact::test {

constexpr double kPi = 3.14159265358979323846;

struct Hertz {
  double radius = 0.02;        // m (40 mm ball)
  double e_star = 115.4e9;     // Pa
  double approach = 0.241e-6;  // m (seed ball under its own weight)
  double a() const { return std::sqrt(radius * approach); }
  double force() const { return 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(approach, 1.5); }
  double p0() const { return 2.0 * e_star * a() / (kPi * radius); }
  double stiffness() const { return 2.0 * e_star * a(); }

  // Odd n, ball centred on the middle cell, `cells` cells per contact radius, half-width `span`·a.
  Grid grid(double cells, double span = 1.25) const {
    const double dx = a() / cells;
    const std::size_t half = static_cast<std::size_t>(std::ceil(span * cells));
    return Grid{2 * half + 1, 2 * half + 1, dx, dx};
  }
};

}  // namespace rollspec::contact::test
