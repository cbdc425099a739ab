// Contact history through the solver: x_f and g_st evolve while in contact and are reset on
// separation (seed 000 end of Sec. 3), so that a new contact starts from the projection of the
// node with no accumulated slip.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/solver.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;

TEST_CASE("contact state resets on separation and restarts at the new projection") {
  for (const bool spin : {true, false}) {
    const double r = 0.1;
    Model m;
    const int n = m.add_node(Vector3d(0, 0, r));
    m.bodies.push_back(RigidBody{n, 1.0, 0.004 * Eigen::Matrix3d::Identity()});  // solid sphere 2/5 m r^2
    m.planes.push_back(make_plane(Vector3d::Zero(), Vector3d::UnitZ()));
    m.contacts.push_back(ContactPair{n, 0, ContactLaw{r, 0.3, 1e6, 1e5, true}});
    // press, slide/roll along x, lift, move while lifted, press again
    m.imposed.push_back(ImposedDof{n, 0, 1.0, TimeSeries{{0, 0.1, 0.2, 0.3, 0.4, 0.5}, {0, 0, 0.05, 0.05, 0.1, 0.1}}});
    m.imposed.push_back(ImposedDof{n, 1, 0.0, TimeSeries::constant()});
    m.imposed.push_back(
        ImposedDof{n, 2, 1.0, TimeSeries{{0, 0.1, 0.2, 0.3, 0.4, 0.5}, {0, -1e-3, -1e-3, 0.01, 0.01, -1e-3}}});
    if (!spin)  // rotations held: the sphere slides instead of rolling
      for (int d = 3; d < 6; ++d) m.imposed.push_back(ImposedDof{n, d, 0.0, TimeSeries::constant()});
    SolverOptions o;
    o.force_tol = 1e-8;
    Solver S(m, o);
    auto go = [&](double t_end) {
      while (S.time() < t_end - 1e-9) REQUIRE(S.advance(S.time() + 1e-3).converged);
    };
    go(0.2);
    const ContactState s_in = S.contact_states()[0];
    CHECK(s_in.active);
    if (spin) CHECK(s_in.x_f.x() > 0.04);    // the fictitious point followed the rolling (D-13)
    if (!spin) CHECK(s_in.g_st.x() > 0.04);  // ... or the slip accumulated
    CHECK(std::abs(s_in.x_f.z()) < 1e-15);   // and stays on the plane
    go(0.35);
    const ContactState s_off = S.contact_states()[0];
    CHECK(!S.contacts()[0].active);
    CHECK(!s_off.active);
    CHECK(s_off.x_f.norm() == 0.0);
    CHECK(s_off.g_st.norm() == 0.0);
    go(0.5);
    CHECK(S.pattern_analyses() == (spin ? 1 : 0));  // contacts opened and closed, pattern analysed once
    const ContactState s_re = S.contact_states()[0];
    MESSAGE("spin " << spin << ": in contact x_f " << s_in.x_f.transpose() << " g_st " << s_in.g_st.transpose()
                    << "; after re-contact x_f " << s_re.x_f.transpose() << " g_st " << s_re.g_st.transpose());
    CHECK(s_re.active);
    if (!spin) {  // restarted at the projection of the node, no slip carried over
      CHECK(std::abs(s_re.x_f.x() - 0.1) < 1e-15);
      CHECK(s_re.g_st.norm() == 0.0);
    } else {  // the sphere still spins on landing (free rotation, no damping): it slips from there
      CHECK(std::abs(s_re.x_f.x() - 0.1) < 1e-3);
      CHECK(s_re.g_st.norm() < 1e-3);
    }
  }
}
