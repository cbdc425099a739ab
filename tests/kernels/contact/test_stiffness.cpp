// Frozen-set stiffness k = dP/dw (README Eq. 11) against central finite differences of P(w).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;

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
    worst = std::max(worst, std::fabs(r.stiffness / k_fd - 1.0));
  }
  return worst;
}
}  // namespace

TEST_CASE("frozen-set stiffness agrees with central differences (Hertz)") {
  const Hertz h;
  const Grid grid = h.grid(16.0, 1.4);
  const auto gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.tolerance = 1e-12;
  const double worst = worst_fd_mismatch(solver, gap, {0.8 * h.approach, h.approach, 1.15 * h.approach}, opt, 1e-5);
  MESSAGE("Hertz: max |k_frozen / k_fd - 1| = " << worst);
  CHECK(worst < 1e-3);
}

TEST_CASE("frozen-set stiffness agrees with central differences (rough, elastic-plastic)") {
  const Hertz h;
  const Grid grid = h.grid(12.0, 1.6);
  const auto gap = rollspec::contact::test::wavy_ball_gap(h, grid);
  ContactSolver solver(grid, h.e_star);
  SolverOptions opt;
  opt.tolerance = 1e-12;
  opt.hardness = 0.5 * h.p0();
  std::vector<double> p;
  const ContactResult r = solver.solve(gap, h.approach, p, opt);
  REQUIRE(r.plastic_cells > 0);  // the frozen set really has saturated cells
  const double worst = worst_fd_mismatch(solver, gap, {0.7 * h.approach, h.approach, 1.3 * h.approach}, opt, 1e-5);
  MESSAGE("rough elastic-plastic: max |k_frozen / k_fd - 1| = " << worst << " (plastic cells at w0: " << r.plastic_cells << ")");
  CHECK(worst < 1e-3);
}
