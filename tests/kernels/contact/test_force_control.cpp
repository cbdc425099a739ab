// Approach for a given force (safeguarded Newton on w with the frozen-set stiffness).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/force_control.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/sweep.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;

TEST_CASE("solve_force: Hertz approach under the seed ball's weight") {
  const Hertz h;  // w0 = 0.241 µm is the Hertz approach for P = 2.58 N
  const Grid grid = h.grid(16.0, 1.4);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> p;
  SolverOptions opt;
  opt.tolerance = 1e-12;
  const ContactResult r = solve_force(solver, gap, h.force(), p, opt);
  REQUIRE(r.converged);
  MESSAGE("solve_force Hertz: w / w_Hertz - 1 = " << r.approach / h.approach - 1.0);
  CHECK(std::fabs(r.force / h.force() - 1.0) <= 1e-10);
  // Discretisation: force error at fixed w is 1.2e-4 at 16 cells/a, so w is off by ≈ 2/3 of it.
  CHECK(std::fabs(r.approach / h.approach - 1.0) < 1.5e-4);
  CHECK(solve_force(solver, gap, 0.0, p, opt).force == 0.0);
}

TEST_CASE("solve_force: rough elastic-plastic ball lands between the bracketing sweep steps") {
  const Hertz h;
  const Grid grid = h.grid(10.0, 1.6);
  const auto gap = rollspec::contact::test::wavy_ball_gap(h, grid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.hardness = 0.5 * h.p0();
  const std::vector<double> approaches{0.9 * h.approach, 1.1 * h.approach};
  const auto steps = sweep(solver, gap, approaches, opt);
  REQUIRE(all_converged(steps));
  const double target = 0.5 * (steps[0].force + steps[1].force);
  std::vector<double> p;
  const ContactResult r = solve_force(solver, gap, target, p, opt);
  REQUIRE(r.converged);
  CHECK(r.plastic_cells > 0);
  CHECK(std::fabs(r.force / target - 1.0) <= 1e-10);
  CHECK(r.approach > approaches[0]);
  CHECK(r.approach < approaches[1]);
}

TEST_CASE("solve_force reports failure when the solve budget is too small") {
  const Hertz h;
  const Grid grid = h.grid(8.0, 1.4);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> p;
  ForceControlOptions control;
  control.max_solves = 3;
  const ContactResult r = solve_force(solver, gap, h.force(), p, {}, control);
  CHECK_FALSE(r.converged);
}
