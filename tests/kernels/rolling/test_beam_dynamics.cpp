// Beam dynamics (consistent mass, rotary inertia, Newmark with Rodrigues rotations):
// first bending frequency of a cantilever against Euler-Bernoulli, energy conservation of
// the undamped trapezoidal rule, and the circular section constants.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/solver.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;

TEST_CASE("circular section constants (solid and tube, Cowper shear coefficient)") {
  const double pi = 3.14159265358979323846;
  const BeamSection s = circular_section(2e11, 0.3, 7850, 0.1);
  const double A = pi * 0.05 * 0.05, I = pi * std::pow(0.05, 4) / 4;
  CHECK(s.EA == doctest::Approx(2e11 * A).epsilon(1e-14));
  CHECK(s.EI2 == doctest::Approx(2e11 * I).epsilon(1e-14));
  CHECK(s.GJ == doctest::Approx(2e11 / 2.6 * 2 * I).epsilon(1e-14));
  CHECK(s.GA2 / (2e11 / 2.6 * A) == doctest::Approx(6 * 1.3 / (7 + 6 * 0.3)).epsilon(1e-14));
  CHECK(s.rhoJ1 == doctest::Approx(7850 * 2 * I).epsilon(1e-14));
  const BeamSection t = circular_section(2e11, 0.3, 7850, 0.1, 0.08);
  const double At = pi * (0.05 * 0.05 - 0.04 * 0.04), It = pi * (std::pow(0.05, 4) - std::pow(0.04, 4)) / 4;
  CHECK(t.EA == doctest::Approx(2e11 * At).epsilon(1e-14));
  CHECK(t.EI3 == doctest::Approx(2e11 * It).epsilon(1e-14));
  CHECK(t.outer_radius == 0.05);
  // thin tube: Cowper's coefficient tends to 2(1+nu)/(4+3nu)
  const BeamSection thin = circular_section(2e11, 0.3, 7850, 0.1, 0.0999);
  CHECK(thin.GA2 / (2e11 / 2.6 * thin.EA / 2e11) == doctest::Approx(2 * 1.3 / (4 + 0.9)).epsilon(1e-3));
}

TEST_CASE("cantilever free vibration: first frequency 1.8751^2 sqrt(EI/(rho A L^4)), energy conserved" *
          doctest::test_suite("long")) {
  const double pi = 3.14159265358979323846;
  const double L = 2.0;
  Model m;
  m.sections.push_back(circular_section(2e11, 0.3, 7850, 0.02));  // L/r = 200
  const BeamSection& s = m.sections[0];
  const std::vector<int> ids = add_straight_beam(m, Vector3d::Zero(), Vector3d(L, 0, 0), 10, 0);
  for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids[0], d, 0.0, TimeSeries::constant()});
  // small suddenly applied tip force: oscillation about the static deflection
  const double F = 1e-3 * 3 * s.EI2 / (L * L * L);  // static tip deflection 1e-3 m
  m.loads.push_back(NodalLoad{ids.back(), Vector3d(0, 0, F), Vector3d::Zero(), TimeSeries::constant()});
  const double w1 = 1.8751040687 * 1.8751040687 * std::sqrt(s.EI2 / (s.rhoA * std::pow(L, 4)));
  const double T1 = 2 * pi / w1;
  SolverOptions o;
  o.analysis = Analysis::Dynamic;
  o.consistent_initial_acceleration = true;
  o.force_tol = 1e-10 * F;
  o.disp_tol = 1e-15;
  RunOptions ro;
  ro.dt = T1 / 200;
  ro.t_end = 12.0 * T1;  // many periods: higher modes shift single crossings
  ro.record_nodes = {ids.back()};
  const History h = run(m, o, ro);
  REQUIRE(h.completed);
  // upward zero crossings of w - w_static (linear interpolation)
  const double ws = 1e-3;
  std::vector<double> up;
  for (std::size_t k = 1; k < h.time.size(); ++k) {
    const double a = h.position[k - 1][0].z() - ws, b = h.position[k][0].z() - ws;
    if (a < 0 && b >= 0) up.push_back(h.time[k - 1] + (h.time[k] - h.time[k - 1]) * a / (a - b));
  }
  REQUIRE(up.size() >= 2);
  const double T = (up.back() - up.front()) / double(up.size() - 1);
  double drift = 0;
  for (const Energies& E : h.energy) drift = std::max(drift, std::abs(E.balance()));
  const double Emax = F * 2e-3;  // work scale of the load
  MESSAGE("period " << T << " vs Euler-Bernoulli " << T1 << " (rel " << T / T1 - 1 << "), max |energy balance| "
                    << drift << " J vs work scale " << Emax << ", Newton its " << h.newton_iterations << ", cuts "
                    << h.cuts);
  // Timoshenko + rotary inertia lengthen the period by O((r/L)^2), Newmark by O((w dt)^2)
  CHECK(std::abs(T / T1 - 1) < 0.002);
  CHECK(drift < 1e-3 * Emax);
}
