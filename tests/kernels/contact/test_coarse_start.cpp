// Coarse start of a cold solve (README Eq. 16) against the line-search start: the same solution,
// fewer iterations on the fine grid.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;

TEST_CASE("coarse start: the same Hertz solution in fewer fine-grid iterations") {
  const Hertz h;
  const double dx = h.a() / 24.0;  // 24 cells per contact radius, even 128² (coarse 64², 32²)
  const Grid grid{128, 128, dx, dx};
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.tolerance = 1e-12;
  std::vector<double> p_line, p_coarse;
  opt.coarse_start = false;
  const ContactResult line = solver.solve(gap, h.approach, p_line, opt);
  opt.coarse_start = true;
  const ContactResult coarse = solver.solve(gap, h.approach, p_coarse, opt);
  REQUIRE(line.converged);
  REQUIRE(coarse.converged);
  MESSAGE("Hertz 128^2 cold solve: line-search start " << line.iterations << " iterations, coarse start "
                                                       << coarse.iterations << " + " << coarse.coarse_iterations
                                                       << " on the coarse grids");
  CHECK(line.coarse_iterations == 0);
  CHECK(coarse.coarse_iterations > 0);
  CHECK(coarse.iterations < line.iterations);
  // Both meet the stopping rule of Eq. 9 at 1e-12: the fields agree to that order.
  CHECK(coarse.force == doctest::Approx(line.force).epsilon(1e-10));
  CHECK(coarse.stiffness == doctest::Approx(line.stiffness).epsilon(1e-9));
  CHECK(coarse.contact_cells == line.contact_cells);
  CHECK(coarse.force == doctest::Approx(h.force()).epsilon(2e-4));
}

TEST_CASE("coarse start: only on even grids of at least 64 cells each way") {
  const Hertz h;
  SolverOptions opt;
  for (const Grid grid : {h.grid(16.0), Grid{62, 128, h.a() / 16.0, h.a() / 16.0}}) {
    ContactSolver solver(grid, h.e_star);
    std::vector<double> p;
    const ContactResult r = solver.solve(ball_gap(grid, h.radius, {}), h.approach, p, opt);
    CHECK(r.converged);
    CHECK(r.coarse_iterations == 0);
  }
}
