// Frozen-set stiffness k = dP/dw (README Eq. 11) against central finite differences of P(w); the
// stiffness with the sub-cell contact edge (README Eq. 13–15) against the slope of P(w) over one
// cell of edge travel.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;
using rollspec::contact::test::HertzBall;
using rollspec::contact::test::WavyPlasticBall;

namespace {
// Largest |k_frozen / k_fd − 1| over the given approaches, step dw = rel_step · w.
double worst_fd_mismatch(ContactSolver& solver, const std::vector<double>& gap, const std::vector<double>& approaches,
                         const SolverOptions& opt, double rel_step) {
  double worst = 0.0;
  for (double w : approaches) {
    std::vector<double> p;
    const ContactResult r = solver.solve(gap, w, p, opt);
    REQUIRE(r.converged);
    REQUIRE(r.stiffness_converged);
    std::vector<double> pp = p, pm = p;
    const double dw = rel_step * w;
    const ContactResult rp = solver.solve(gap, w + dw, pp, opt), rm = solver.solve(gap, w - dw, pm, opt);
    REQUIRE(rp.converged);
    REQUIRE(rm.converged);
    const double k_fd = (rp.force - rm.force) / (2 * dw);
    worst = std::max(worst, std::fabs(r.frozen_stiffness / k_fd - 1.0));
  }
  return worst;
}
}  // namespace

TEST_CASE("frozen-set stiffness agrees with central differences (Hertz)") {
  HertzBall ball(16.0, 1.4);
  auto& [h, grid, gap, solver, opt] = ball;
  opt.tolerance = 1e-12;
  const double worst = worst_fd_mismatch(solver, gap, {0.8 * h.approach, h.approach, 1.15 * h.approach}, opt, 1e-5);
  MESSAGE("Hertz: max |k_frozen / k_fd - 1| = " << worst);
  CHECK(worst < 1e-3);
}

TEST_CASE("frozen-set stiffness agrees with central differences (rough, elastic-plastic)") {
  WavyPlasticBall ball(12.0, 1.6);
  auto& [h, grid, gap, solver, opt] = ball;
  opt.tolerance = 1e-12;
  std::vector<double> p;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  REQUIRE(r.plastic_cells > 0);  // the frozen set really has saturated cells
  const double worst = worst_fd_mismatch(solver, gap, {0.7 * h.approach, h.approach, 1.3 * h.approach}, opt, 1e-5);
  MESSAGE("rough elastic-plastic: max |k_frozen / k_fd - 1| = " << worst << " (plastic cells at w0: " << r.plastic_cells
                                                                << "; sub-cell edge correction at w0 δk/k_frozen = "
                                                                << r.edge_correction / r.frozen_stiffness << ")");
  CHECK(worst < 1e-3);
}

TEST_CASE("sub-cell edge stiffness equals the slope of P(w) over one cell of edge travel (Hertz, 32 cells/a)") {
  // The discrete P(w) is piecewise linear (a kink each time cells enter), so its slope over an
  // interval in which the edge moves by one cell averages the frozen-set staircase; the sub-cell
  // edge stiffness at the centre must agree with it. Edge travel da = dx ⇔ dw = 2 w dx / a.
  const Hertz h;
  const double cells = 32.0;
  const Grid grid = h.grid(cells, 1.4);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.tolerance = 1e-12;
  double worst_edge = 0.0, worst_frozen = 0.0;
  for (double f : {0.97, 1.0, 1.03}) {
    const double w = f * h.approach, dw = w / cells;  // ± half a cell of edge travel
    std::vector<double> p;
    const ContactResult r = solver.solve(gap, w, p, opt);
    REQUIRE(r.converged);
    REQUIRE(r.stiffness_converged);
    std::vector<double> pp = p, pm = p;
    const ContactResult rp = solver.solve(gap, w + dw, pp, opt), rm = solver.solve(gap, w - dw, pm, opt);
    REQUIRE(rp.converged);
    REQUIRE(rm.converged);
    const double k_slope = (rp.force - rm.force) / (2 * dw);
    worst_edge = std::max(worst_edge, std::fabs(r.stiffness / k_slope - 1.0));
    worst_frozen = std::max(worst_frozen, std::fabs(r.frozen_stiffness / k_slope - 1.0));
  }
  MESSAGE("Hertz 32 cells/a: max |k / k_slope - 1| = " << worst_edge << " with the sub-cell edge, " << worst_frozen
                                                       << " frozen set alone");
  CHECK(worst_edge < 1e-3);
  CHECK(worst_edge < worst_frozen);
}
