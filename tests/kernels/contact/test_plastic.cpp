// Pressure cap H (kernels/README.md D-7): saturation, the elastic limit H → ∞, the fully plastic limit.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;
using rollspec::contact::test::HertzBall;
using rollspec::contact::test::kPi;
using rollspec::contact::test::WavyPlasticBall;

TEST_CASE("no cell above H; plastic cells and plastic volume reported") {
  HertzBall ball(16.0, 1.5);
  auto& [h, grid, gap, solver, opt] = ball;
  opt.hardness = 0.6 * h.p0();
  opt.tolerance = 1e-11;
  std::vector<double> p;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  REQUIRE(r.converged);
  std::size_t at_cap = 0;
  for (double v : p) {
    CHECK(v <= opt.hardness);
    at_cap += v == opt.hardness;
  }
  CHECK(r.max_pressure == opt.hardness);
  CHECK(r.plastic_cells == at_cap);
  CHECK(r.plastic_cells > 0);
  CHECK(r.plastic_volume > 0.0);
  // A capped solve carries less load and spreads wider than the elastic one.
  std::vector<double> pe;
  SolverOptions elastic = opt;
  elastic.hardness = std::numeric_limits<double>::infinity();
  const ContactResult re = solver.solve(gap, h.approach, pe, elastic);
  CHECK(r.force < re.force);
  CHECK(r.contact_cells > re.contact_cells);
  MESSAGE("H = 0.6 p0: P/P_elastic = " << r.force / re.force << ", plastic cells " << r.plastic_cells
                                       << ", plastic volume " << r.plastic_volume << " m^3, iterations "
                                       << r.iterations);
}

TEST_CASE("H -> infinity reproduces the uncapped (Hertz) solve bitwise") {
  const Hertz h;
  const Grid grid = h.grid(16.0);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  std::vector<double> p_inf, p_big;
  SolverOptions opt;  // default hardness = +inf
  const ContactResult r_inf = solver.solve(gap, h.approach, p_inf, opt);
  opt.hardness = 1e3 * h.p0();
  const ContactResult r_big = solver.solve(gap, h.approach, p_big, opt);
  REQUIRE(r_inf.converged);
  CHECK(p_big == p_inf);
  CHECK(r_big.force == r_inf.force);
  CHECK(r_big.iterations == r_inf.iterations);
  CHECK(r_big.plastic_cells == 0);
  CHECK(std::fabs(r_inf.force / h.force() - 1.0) < 2e-4);
}

TEST_CASE("H = 0.01 p0: force within 2 % of the bearing-area limit 2 pi R delta H") {
  const Hertz h;
  const Grid grid = h.grid(24.0, 1.6);  // contact radius → sqrt(2) a
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.hardness = 0.01 * h.p0();
  std::vector<double> p;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  REQUIRE(r.converged);
  const double limit = 2 * kPi * h.radius * h.approach * opt.hardness;
  MESSAGE("H = 0.01 p0: P / (2 pi R delta H) - 1 = " << r.force / limit - 1.0 << ", plastic share "
                                                     << double(r.plastic_cells) / double(r.contact_cells));
  CHECK(std::fabs(r.force / limit - 1.0) < 0.02);
  CHECK(r.max_pressure <= opt.hardness);
  // Plastic volume (README Eq. 10): rigid-plastic limit ∫(w − r²/2R) dA = π R w²; the small elastic
  // displacement under H lowers it by a few per cent.
  const double v_rigid = kPi * h.radius * h.approach * h.approach;
  MESSAGE("H = 0.01 p0: plastic volume / (pi R w^2) - 1 = " << r.plastic_volume / v_rigid - 1.0);
  CHECK(r.plastic_volume < v_rigid);
  CHECK(r.plastic_volume > 0.95 * v_rigid);
}

TEST_CASE("rough ball: cap holds, saturated cells are released when unloading") {
  WavyPlasticBall ball(12.0, 1.6);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> p;
  const ContactResult high = solver.solve(gap, 1.2 * h.approach, p, opt);
  REQUIRE(high.converged);
  REQUIRE(high.plastic_cells > 0);
  // Warm start from the high-load field at a lower approach: many saturated cells must leave H.
  std::vector<double> p_warm = p, p_cold;
  const ContactResult low_warm = solver.solve(gap, 0.6 * h.approach, p_warm, opt);
  const ContactResult low_cold = solver.solve(gap, 0.6 * h.approach, p_cold, opt);
  REQUIRE(low_warm.converged);
  REQUIRE(low_cold.converged);
  CHECK(low_warm.plastic_cells < high.plastic_cells);
  CHECK(low_warm.force == doctest::Approx(low_cold.force).epsilon(1e-8));
  for (double v : p_warm) CHECK(v <= opt.hardness);
}

TEST_CASE("warm start with every cell saturated (empty CG set) converges to the cold solution") {
  WavyPlasticBall ball(8.0, 1.6);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> p_sat(grid.size(), opt.hardness), p_cold;
  const ContactResult sat = solver.solve(gap, h.approach, p_sat, opt);
  const ContactResult cold = solver.solve(gap, h.approach, p_cold, opt);
  REQUIRE(cold.converged);
  CHECK(sat.converged);
  CHECK(sat.force == doctest::Approx(cold.force).epsilon(1e-8));
  CHECK(sat.plastic_cells == cold.plastic_cells);
}
