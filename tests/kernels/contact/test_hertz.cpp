// Hertz: smooth paraboloid at fixed approach against the continuum solution (kernels/README.md (contact)).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/sweep.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;
using rollspec::contact::test::HertzBall;
using rollspec::contact::test::kPi;

namespace {
struct HertzErrors {
  double force, pmax, radius, stiffness;
  ContactResult res;
};

HertzErrors hertz_errors(double cells) {
  HertzBall ball(cells);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> p;
  opt.tolerance = 1e-12;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  REQUIRE(r.converged);
  REQUIRE(r.stiffness_converged);
  HertzErrors e{};
  e.force = r.force / h.force() - 1.0;
  e.pmax = r.max_pressure / h.p0() - 1.0;
  e.radius = std::sqrt(r.contact_area / kPi) / h.a() - 1.0;
  e.stiffness = r.stiffness / h.stiffness() - 1.0;
  e.res = r;
  MESSAGE("Hertz " << cells << " cells/a: force " << e.force << ", p_max " << e.pmax << ", radius " << e.radius
                   << ", k " << e.stiffness << ", iterations " << r.iterations << ", error " << r.error);
  return e;
}
}  // namespace

TEST_CASE("Hertz sphere at 32 cells per contact radius") {
  const HertzErrors e = hertz_errors(32.0);
  CHECK(std::fabs(e.force) < 1e-4);
  CHECK(std::fabs(e.pmax) < 3e-4);
  CHECK(std::fabs(e.radius) < 1e-2);
  CHECK(e.res.plastic_cells == 0);
  CHECK(e.res.plastic_volume == 0.0);
}

TEST_CASE("Hertz error falls as the grid refines (8, 16, 32, 64 cells per radius)") {
  const HertzErrors e8 = hertz_errors(8.0), e16 = hertz_errors(16.0), e32 = hertz_errors(32.0),
                    e64 = hertz_errors(64.0);
  CHECK(std::fabs(e16.force) < std::fabs(e8.force));
  CHECK(std::fabs(e32.force) < std::fabs(e16.force));
  CHECK(std::fabs(e64.force) < std::fabs(e32.force));
  CHECK(std::fabs(e16.pmax) < std::fabs(e8.pmax));
  CHECK(std::fabs(e32.pmax) < std::fabs(e16.pmax));
  CHECK(std::fabs(e64.pmax) < std::fabs(e32.pmax));
  CHECK(std::fabs(e64.radius) < std::fabs(e8.radius));
}

namespace {
// Stiffness error against 2E*a along 11 approaches in [0.95, 1.05] w0 (one sweep): the frozen-set
// k (README Eq. 11) and the stiffness with the sub-cell contact edge (README Eq. 13–15).
struct StiffnessErrors {
  double mean, rms, worst;
};
struct StiffnessPair {
  StiffnessErrors frozen, edge;
};
StiffnessPair stiffness_errors(double cells) {
  Hertz h;
  const double w0 = h.approach;
  const Grid grid = h.grid(cells, 1.35);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> approaches;
  for (int j = 0; j <= 10; ++j) approaches.push_back(w0 * (0.95 + 0.01 * j));
  SolverOptions opt;
  opt.tolerance = 1e-12;
  const auto results = sweep(solver, gap, approaches, opt);
  REQUIRE(all_converged(results));
  StiffnessPair e{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const double count = static_cast<double>(results.size());
  auto add = [count](StiffnessErrors& s, double err) {
    s.mean += err / count;
    s.rms += err * err / count;
    s.worst = std::max(s.worst, std::fabs(err));
  };
  for (std::size_t j = 0; j < results.size(); ++j) {
    REQUIRE(results[j].stiffness_converged);
    h.approach = approaches[j];
    add(e.frozen, results[j].frozen_stiffness / h.stiffness() - 1.0);
    add(e.edge, results[j].stiffness / h.stiffness() - 1.0);
    CHECK(results[j].stiffness == results[j].frozen_stiffness + results[j].edge_correction);
  }
  e.frozen.rms = std::sqrt(e.frozen.rms);
  e.edge.rms = std::sqrt(e.edge.rms);
  MESSAGE("Hertz k vs 2E*a, " << cells << " cells/a, 11 approaches: frozen set mean " << e.frozen.mean << ", rms "
                              << e.frozen.rms << ", worst " << e.frozen.worst << "; with sub-cell edge mean "
                              << e.edge.mean << ", rms " << e.edge.rms << ", worst " << e.edge.worst);
  return e;
}
}  // namespace

TEST_CASE("Hertz stiffness k = 2 E* a with the sub-cell contact edge (issue 4: within 1e-3 at 32 cells/a)") {
  // The frozen-set k alone is the exact derivative of the discrete P(w) (test_stiffness), which
  // jumps each time cells enter contact: pointwise it scatters around 2E*a (32 cells/a: up to
  // 2.2e-3 at these 11 approaches). The sub-cell edge (README Eq. 13–15) removes the scatter; its
  // remaining error is a first-order bias (≈ +0.016 dx/a) that falls with refinement.
  const StiffnessPair e16 = stiffness_errors(16.0), e32 = stiffness_errors(32.0), e64 = stiffness_errors(64.0);
  CHECK(e32.edge.worst < 1e-3);  // the criterion, pointwise at every approach
  CHECK(e32.edge.worst < e32.frozen.worst);
  CHECK(e64.edge.worst < e32.edge.worst);
  CHECK(e32.edge.worst < e16.edge.worst);
  CHECK(e64.edge.worst < 5e-4);
  // The frozen-set k: unbiased on average, scatter falling with refinement.
  CHECK(std::fabs(e32.frozen.mean) < 1e-3);
  CHECK(e32.frozen.rms < e16.frozen.rms);
  CHECK(e64.frozen.rms < e32.frozen.rms);
}

TEST_CASE("zero approach: no contact, zero force, converged") {
  const Hertz h;
  const Grid grid = h.grid(8.0);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Sphere);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> p(grid.size(), 1e6);  // a stale warm start must not survive
  const ContactResult r = solver.solve(gap, 0.0, p);
  CHECK(r.converged);
  CHECK(r.force == 0.0);
  CHECK(r.contact_cells == 0);
  CHECK(r.stiffness == 0.0);
  for (double v : p) CHECK(v == 0.0);
}

TEST_CASE("non-convergence is reported when the iteration limit is tiny") {
  HertzBall ball(16.0);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> p;
  opt.max_iterations = 2;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  CHECK_FALSE(r.converged);
  CHECK(r.iterations == 2);
  CHECK(r.error >= opt.tolerance);
}

TEST_CASE("input checks") {
  const Hertz h;
  const Grid grid = h.grid(4.0);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> p;
  CHECK_THROWS_AS(solver.solve(std::vector<double>(3, 0.0), 1e-7, p), std::invalid_argument);
  SolverOptions opt;
  opt.hardness = 0.0;
  const auto gap = ball_gap(grid, h.radius, {});
  CHECK_THROWS_AS(solver.solve(gap, 1e-7, p, opt), std::invalid_argument);
  CHECK_THROWS_AS(effective_modulus(-1.0, 0.3, 1.0, 0.3), std::invalid_argument);
  CHECK(effective_modulus(210e9, 0.3, 210e9, 0.3) == doctest::Approx(210e9 / (2.0 * (1.0 - 0.09))).epsilon(1e-15));
}

TEST_CASE("load control on the open half-space finds the Hertz approach") {
  HertzBall ball(16.0);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> p;
  opt.tolerance = 1e-12;
  const double mean_pressure = h.force() / (static_cast<double>(grid.size()) * grid.cell_area());
  const ContactResult r = solver.solve_load(gap, mean_pressure, p, opt);
  REQUIRE(r.converged);
  MESSAGE("load control, 16 cells/a: w / w_Hertz - 1 = " << r.approach / h.approach - 1.0 << ", iterations "
                                                         << r.iterations);
  CHECK(r.force == doctest::Approx(h.force()).epsilon(1e-12));
  // P ∝ w^{3/2}: the approach error is 2/3 of the force error at fixed approach (1.2e-4 here).
  CHECK(std::fabs(r.approach / h.approach - 1.0) < 1.5e-4);
  // Same field as displacement control at the approach it found.
  std::vector<double> pd;
  const ContactResult rd = solver.solve(gap, r.approach, pd, opt);
  CHECK(rd.force == doctest::Approx(r.force).epsilon(1e-9));
}
