#pragma once
// A deterministic rough ball contact (no RNG in tests): paraboloid plus a few crossed waves.
#include <cmath>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"

namespace rollspec::contact::test {

inline std::vector<double> wavy_heights(const Grid& grid, double amplitude, double wavelength) {
  std::vector<double> h(grid.size());
  const double q = 2 * kPi / wavelength;
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix) {
      const double x = grid.x(ix), y = grid.y(iy);
      h[iy * grid.nx + ix] = amplitude * (0.6 * std::cos(q * x + 0.3) * std::cos(1.3 * q * y) +
                                          0.4 * std::sin(2.1 * q * (x + 0.5 * y) + 1.0));
    }
  return h;
}

// The rough ball the elastic-plastic tests share: the Hertz ball of `h` with waves of 0.15 times
// its approach and 0.4 times its contact radius.
inline std::vector<double> wavy_ball_gap(const Hertz& h, const Grid& grid) {
  return ball_gap(grid, h.radius, wavy_heights(grid, 0.15 * h.approach, 0.4 * h.a()));
}

// That rough ball on a grid of `cells_per_radius` cells per contact radius over `extent` contact radii, its
// solver, and the elastic-plastic options the tests share (hardness 0.5 p0). Taken apart by a structured
// binding: auto& [h, grid, gap, solver, opt] = ball.
struct WavyPlasticBall {
  Hertz h;
  Grid grid;
  std::vector<double> gap;
  ContactSolver solver;
  SolverOptions opt;
  WavyPlasticBall(double cells_per_radius, double extent)
      : grid(h.grid(cells_per_radius, extent)), gap(wavy_ball_gap(h, grid)), solver(grid, h.e_star) {
    opt.hardness = 0.5 * h.p0();
  }
};

}  // namespace rollspec::contact::test
