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
using rollspec::contact::test::WavyPlasticBall;

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
  WavyPlasticBall ball(10.0, 1.6);
  auto& [h, grid, gap, solver, opt] = ball;
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

// Load control on the open half-space (README Eq. 17) against the Newton of solve_force (the
// reference): the same discrete problem, both to the stopping rule 1e-10 and |P − F| ≤ 1e-10 F.
TEST_CASE("solve_at_force: load control equals the Newton on the approach (Hertz, rough elastic-plastic)") {
  const Hertz h;
  SolverOptions opt;
  opt.tolerance = 1e-10;
  for (const bool rough : {false, true}) {
    const Grid grid = h.grid(rough ? 10.0 : 16.0, 1.6);
    const auto gap =
        rough ? rollspec::contact::test::wavy_ball_gap(h, grid) : ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
    SolverOptions o = opt;
    if (rough) o.hardness = 0.5 * h.p0();
    ContactSolver solver(grid, h.e_star);
    std::vector<double> p_ref;
    const ContactResult ref = solve_force(solver, gap, h.force(), p_ref, o);
    REQUIRE(ref.converged);
    // Cold without a hint (uniform start), cold from the interference at a hint 5 % off, and warm
    // from the reference field with that hint.
    for (int start = 0; start < 3; ++start) {
      std::vector<double> p = start == 2 ? p_ref : std::vector<double>{};
      const double hint = start == 0 ? std::nan("") : 1.05 * ref.approach;
      const ContactResult r = solver.solve_at_force(gap, h.force(), p, o, hint);
      REQUIRE(r.converged);
      MESSAGE((rough ? "rough" : "Hertz") << " start " << start << ": " << r.iterations << " iterations, w − w_ref = "
                                          << (r.approach - ref.approach) / h.approach << " δ_H, plastic cells "
                                          << r.plastic_cells << " (reference " << ref.plastic_cells << ")");
      CHECK(r.error < o.tolerance);
      CHECK(std::fabs(r.force / h.force() - 1.0) <= 1e-13);  // the constraint holds to rounding
      CHECK(std::fabs(r.approach - ref.approach) < 1e-8 * h.approach);
      CHECK(r.contact_cells == ref.contact_cells);
      CHECK(r.plastic_cells == ref.plastic_cells);
      if (rough) CHECK(r.plastic_cells > 0);
      // A displacement-controlled solve at the returned approach accepts the field as it is.
      std::vector<double> q = p;
      SolverOptions d = o;
      d.compute_stiffness = false;
      const ContactResult check = solver.solve(gap, r.approach, q, d);
      CHECK(check.iterations == 0);
    }
  }
  ContactSolver solver(h.grid(8.0, 1.4), h.e_star);
  std::vector<double> p;
  const auto gap = ball_gap(solver.grid(), h.radius, {}, BallShape::Paraboloid);
  CHECK(solver.solve_at_force(gap, 0.0, p).force == 0.0);
  CHECK_THROWS_AS(solver.solve_at_force(gap, -1.0, p), std::invalid_argument);
}
