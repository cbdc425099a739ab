#pragma once
// Smooth paraboloid on a flat: the continuum Hertz solution (kernels/contact/hertz.hpp) is exact for this gap.
#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/hertz.hpp"

namespace rollspec::contact::test {

constexpr double kPi = 3.14159265358979323846;

struct Hertz {
  double radius = 0.02;        // m (40 mm ball)
  double e_star = 115.4e9;     // Pa
  double approach = 0.241e-6;  // m (seed ball under its own weight)
  double a() const { return hertz::contact_radius_at_approach(radius, approach); }
  double force() const { return hertz::force_at_approach(radius, e_star, approach); }
  double p0() const { return hertz::peak_pressure_at_approach(radius, e_star, approach); }
  double stiffness() const { return hertz::stiffness_at_approach(radius, e_star, approach); }

  // Odd n, ball centred on the middle cell, `cells` cells per contact radius, half-width `span`·a.
  Grid grid(double cells, double span = 1.25) const {
    const double dx = a() / cells;
    const std::size_t half = static_cast<std::size_t>(std::ceil(span * cells));
    return Grid{2 * half + 1, 2 * half + 1, dx, dx};
  }
};

// The smooth paraboloid of `Hertz` on its grid (h.grid's arguments), the solver and default options the
// tests start from. Taken apart by a structured binding: auto& [h, grid, gap, solver, opt] = ball.
struct HertzBall {
  Hertz h;
  Grid grid;
  std::vector<double> gap;
  ContactSolver solver;
  SolverOptions opt;
  explicit HertzBall(double cells, double span = 1.25)
      : grid(h.grid(cells, span)), gap(ball_gap(grid, h.radius, {}, BallShape::Paraboloid)), solver(grid, h.e_star) {}
};

}  // namespace rollspec::contact::test
