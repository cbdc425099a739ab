// Seed 000 example 4.3: a rigid puck between walls (four planes, one contact pair each).
// Frictionless: energy per impact with trapezoidal Newmark, exact balance with the
// energy-consistent integrator (R-50..R-53). mu = 0.4: energy never increases and the
// spin/translation exchange follows rigid-body impulse theory (README R-55).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;

namespace {
History run_puck(const PuckParams& p, Integrator integ, double dt, double t_end) {
  SolverOptions o;
  o.integrator = integ;
  o.force_tol = 1e-7;
  o.disp_tol = 1e-14;
  RunOptions ro;
  ro.dt = dt;
  ro.t_end = t_end;
  return run(puck_model(p), o, ro);
}
}  // namespace

TEST_CASE("frictionless puck between walls: energy per impact, Newmark and energy-consistent") {
  PuckParams p;
  p.half_width = 0.5;
  p.v0 = Vector3d(2.0, 0.0, 0.0);
  p.omega0 = 3.0;
  for (double dt : {1e-3, 1e-4}) {
    const History hn = run_puck(p, Integrator::Newmark, dt, 2.9);
    REQUIRE(hn.completed);
    const std::vector<Impact> in = find_impacts(hn);
    REQUIRE(in.size() >= 10);
    double worst = 0.0;
    for (const Impact& im : in) worst = std::max(worst, std::abs(im.energy_after / im.energy_before - 1.0));
    std::printf("puck mu=0 Newmark dt=%g: %zu impacts, max |dE|/E per impact %.3e, max penetration %.4e\n", dt,
                in.size(), worst, in.front().max_penetration);
    CHECK(worst <= 2e-3);
    // the walls the puck hits are the two x walls, alternately
    CHECK(in[0].pair == 0);
    CHECK(in[1].pair == 1);

    const History he = run_puck(p, Integrator::EnergyConsistent, dt, 2.9);
    REQUIRE(he.completed);
    const std::vector<Impact> ie = find_impacts(he);
    REQUIRE(ie.size() >= 10);
    const double E0 = he.energy.front().kinetic;
    double drift = 0.0, bal = 0.0;
    for (std::size_t k = 0; k < he.time.size(); ++k) {
      const Energies& e = he.energy[k];
      drift = std::max(drift, std::abs(e.kinetic + e.penalty - E0) / E0);
      bal = std::max(bal, std::abs(e.balance_error()) / E0);
    }
    const double after10 = std::abs(ie[9].energy_after / E0 - 1.0);
    std::printf(
        "puck mu=0 energy-consistent dt=%g: %zu impacts, |E_after10/E0 - 1| = %.3e, max step drift %.3e, "
        "balance error %.3e\n",
        dt, ie.size(), after10, drift, bal);
    CHECK(after10 <= 1e-8);
    CHECK(drift <= 1e-8);
    // spin untouched without friction
    CHECK(std::abs(he.angular_velocity.back()[0].y() - p.omega0) < 1e-9);
  }
}
