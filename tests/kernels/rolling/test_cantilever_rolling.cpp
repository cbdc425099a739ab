// Seed 000 example 4.2 (cantilever rolling and sliding on a plane, quasi-static), on a
// coarser mesh than the paper's (20 instead of 100 quadratic elements) to keep the test
// short; the 100-element run is the benchmark bench/rolling. Checks: global equilibrium,
// Coulomb bound on the tip reaction, torsion present with rolling and absent without, and
// the paper's observation that rolling lowers the reaction and the friction work.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;

TEST_CASE("seed 000 example 4.2 (20 elements): rolling gives friction torsion, no rolling does not" *
          doctest::test_suite("long")) {
  CantileverParams p;
  p.n_elements = 20;
  const double A = 0.25 * 3.14159265358979323846 * p.D * p.D;
  const double W = p.rho * A * p.L * p.g;  // beam weight
  const std::vector<double> snaps{1.0, 2.0, 4.0};
  CantileverParams pn = p;
  pn.rolling = false;
  const CantileverRun roll = run_cantilever(p, 4.0, 0.01, snaps);
  const CantileverRun noroll = run_cantilever(pn, 4.0, 0.01, snaps);
  REQUIRE(roll.completed);
  REQUIRE(noroll.completed);
  REQUIRE(roll.snapshots.size() == 3);
  REQUIRE(noroll.snapshots.size() == 3);
  for (const CantileverRun* r : {&roll, &noroll}) {
    for (const CantileverSnapshot& s : r->snapshots) {
      // global equilibrium: contact forces + support reactions + weight = 0
      const Vector3d reac_B(0, s.reaction_y, 0);
      const Vector3d bal = s.contact_force_sum + s.root_reaction + reac_B + Vector3d(0, 0, -W);
      CHECK(bal.norm() < 1e-5 * W);  // Newton stops at ‖R_free‖ ≤ 1e-6 W
      // Coulomb: the lateral force cannot exceed mu times the weight
      CHECK(std::abs(s.reaction_y) < p.mu * W);
    }
    // t = 1: own weight only, carried by the plane (the clamp takes the rest near A), no
    // torsion, nothing slides
    const CantileverSnapshot& s1 = r->snapshots[0];
    CHECK(s1.contact_force_sum.z() + s1.root_reaction.z() == doctest::Approx(W).epsilon(1e-9));
    CHECK(s1.root_reaction.z() < 0.02 * W);
    CHECK(s1.max_abs_torsion < 1e-6 * p.mu * 0.5 * p.D * W);
    CHECK(s1.n_slip == 0);
  }
  const CantileverSnapshot &r2 = roll.snapshots[1], &n2 = noroll.snapshots[1];
  MESSAGE("t = 2, rolling: tip " << r2.tip.transpose() << ", R_y " << r2.reaction_y << ", max |torsion| "
                                 << r2.max_abs_torsion << ", slip/stick " << r2.n_slip << "/" << r2.n_stick);
  MESSAGE("t = 2, no rolling: tip " << n2.tip.transpose() << ", R_y " << n2.reaction_y << ", max |torsion| "
                                    << n2.max_abs_torsion << ", slip/stick " << n2.n_slip << "/" << n2.n_stick);
  MESSAGE("friction work to t = 4: rolling " << roll.friction_dissipation << ", no rolling "
                                             << noroll.friction_dissipation << "; Newton its " << roll.newton_iterations
                                             << " / " << noroll.newton_iterations);
  // the friction moment (C - x_o) x f twists the beam (seed 000 Fig. 13) ...
  const double mu_r_w = p.mu * 0.5 * p.D * W;  // sum of all friction moments at full slip
  CHECK(r2.max_abs_torsion > 0.05 * mu_r_w);
  CHECK(r2.max_abs_torsion < mu_r_w);
  // ... while without rolling there is no torsion beyond round-off of the geometry
  CHECK(n2.max_abs_torsion < 1e-3 * r2.max_abs_torsion);
  // rolling lowers the lateral force and the friction work (seed 000 Fig. 12, 16)
  CHECK(std::abs(r2.reaction_y) < std::abs(n2.reaction_y));
  CHECK(roll.friction_dissipation < noroll.friction_dissipation);
}
