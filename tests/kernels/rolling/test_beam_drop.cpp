// End-to-end dynamics of a flexible beam with rolling contact nodes: a tilted beam dropped
// with a sideways velocity and spin onto a plane with friction (a small version of seed 000
// example 4.4). Energy balance kinetic + strain + penalty - W_gravity + W_friction = const
// up to the normal-penalty kink at opening/closing.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/solver.hpp"
#include "run_options.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;
using rollspec::rolling::test::run_options;

TEST_CASE("flexible beam dropped on a plane with friction: contact, friction, energy balance") {
  Model m;
  m.sections.push_back(circular_section(1e9, 0.3, 2000.0, 0.05));
  const double r = 0.025;
  const std::vector<int> ids =
      add_straight_beam(m, Vector3d(0, 0, r + 0.002), Vector3d(1.0, 0.0, r + 0.02), 4, 0, Vector3d::UnitY());
  m.planes.push_back(make_plane(Vector3d::Zero(), Vector3d::UnitZ()));
  for (int id : ids) m.contacts.push_back(ContactPair{id, 0, ContactLaw{r, 0.3, 1e6, 1e5, true}});
  m.gravity = Vector3d(0, 0, -9.81);
  m.v0.assign(m.X.size(), Vector3d(0.0, 1.0, -0.3));
  m.w0.assign(m.X.size(), Vector3d(2.0, 0.0, 0.0));
  SolverOptions o;
  o.force_tol = 1e-8;
  o.max_line_search = 8;
  const History h = run(m, o, run_options(2e-4, 0.3));
  REQUIRE(h.completed);
  const double E0 = h.energy.front().balance();
  double drift = 0.0, gmin = 0.0, emax = 0.0;
  int n_stick = 0, n_slip = 0;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    drift = std::max(drift, std::abs(h.energy[k].balance() - E0));
    emax = std::max(emax, h.energy[k].kinetic);
    for (const ContactOutput& c : h.contact[k]) {
      gmin = std::min(gmin, c.g_n);
      if (c.active) (c.slip ? n_slip : n_stick) += 1;
    }
  }
  const Energies& Ee = h.energy.back();
  MESSAGE("max penetration " << -gmin << " m, contact records stick/slip " << n_stick << "/" << n_slip
                             << ", friction work " << Ee.friction_work << " J (return mapping "
                             << Ee.friction_dissipation << " J), max |balance drift| " << drift << " J (max kinetic "
                             << emax << " J), Newton its " << h.newton_iterations << ", cuts " << h.cuts);
  CHECK(n_stick > 0);
  CHECK(n_slip > 0);
  CHECK(Ee.friction_dissipation > 0.0);
  CHECK(Ee.friction_work > 0.0);
  CHECK(-gmin < 0.05 * r);  // penalty eps_n = 1e6 for a 4 kg beam landing at 0.3 m/s
  CHECK(drift < 0.01 * emax);
}
