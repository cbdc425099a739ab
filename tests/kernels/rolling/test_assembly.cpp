// Sparse assembly into the recorded pattern (kernels/rolling/assembly, README Sec. 6) against dense
// assembly of the same residual and tangent: beams, a rigid body, loads, an imposed DOF, plane
// pairs and rough-surface pairs with and without friction and damper, all in contact.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/contact_set.hpp"
#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

// A tube of two quadratic elements lying across a wavy grid (pairs with friction and damper on
// the even nodes, frictionless on the odd ones), a plane wall at its first node, a rigid body at
// its middle node, a load and a moment at its last node, the first node's y imposed.
Model tube_on_grid() {
  Model m;
  m.sections.push_back(circular_section(2e9, 0.3, 7800, 0.06, 0.05));
  const double r = 0.03;
  const std::vector<int> ids =
      add_straight_beam(m, Vector3d(0.0, -0.25, r - 1e-3), Vector3d(0.0, 0.25, r - 1e-3), 2, 0, Vector3d::UnitX());
  m.surfaces.push_back(
      grid_height_field(make_plane(Vector3d::Zero(), Vector3d(0.02, 0.01, 1.0)), {-0.4, 0.02, 40}, {-0.4, 0.02, 40},
                        [](double s1, double s2) { return 2e-4 * std::sin(7.0 * s1 + 1.0) * std::cos(5.0 * s2); }));
  for (std::size_t k = 0; k < ids.size(); ++k) {
    SurfaceContactLaw law;
    law.radius = r;
    law.eps_n = 5e5;
    law.mu = k % 2 == 0 ? 0.3 : 0.0;
    law.eps_t = 1e5;
    law.damping = k % 2 == 0 ? 50.0 : 0.0;
    m.surface_contacts.push_back(SurfaceContactPair{ids[k], 0, law});
  }
  m.planes.push_back(make_plane(Vector3d(0.0, -0.25 - r + 1e-3, 0.0), Vector3d::UnitY()));
  m.contacts.push_back(ContactPair{ids[0], 0, ContactLaw{r, 0.3, 5e5, 1e5, true}});
  m.bodies.push_back(RigidBody{ids[2], 0.5, Vector3d(1e-3, 2e-3, 1e-3).asDiagonal()});
  m.loads.push_back(
      NodalLoad{ids[4], Vector3d(0.0, 0.0, -3.0), Vector3d(0.01, 0.0, 0.02), TimeSeries::ramp(0.0, 0.02)});
  m.imposed.push_back(ImposedDof{ids[0], 1, 1e-4, TimeSeries::ramp(0.0, 0.01)});
  m.v0.assign(m.X.size(), Vector3d(0.5, 0.0, -0.05));
  m.w0.assign(m.X.size(), Vector3d(0.0, 0.5 / r, 0.0));
  m.gravity = Vector3d(0, 0, -9.81);
  return m;
}

std::vector<int> free_equations(const Model& m, int& neq) {
  std::vector<int> eq(6 * m.X.size(), 0);
  for (const ImposedDof& d : m.imposed) eq[static_cast<std::size_t>(6 * d.node + d.dof)] = -1;
  neq = 0;
  for (int& e : eq)
    if (e == 0) e = neq++;
  return eq;
}

VectorXd increments(std::size_t nodes, double scale, double phase) {
  VectorXd q(6 * static_cast<Eigen::Index>(nodes));
  for (Eigen::Index k = 0; k < q.size(); ++k) q(k) = scale * std::sin(phase + 0.7 * static_cast<double>(k));
  return q;
}

// Entries of the dense tangent on the free equations equal the sparse ones (and nothing else is
// in the sparse matrix); residuals equal. Both sum the same values in the same order, so exactly.
void check_same(const MatrixXd& Kd, const VectorXd& Rd, const SparseSink& ss, const VectorXd& Rs,
                const std::vector<int>& eq, int min_nonzero) {
  REQUIRE(Rd.size() == Rs.size());
  CHECK((Rd.array() == Rs.array()).all());
  const MatrixXd Ks = MatrixXd(ss.A);
  int differ = 0, nonzero = 0;
  for (std::size_t i = 0; i < eq.size(); ++i)
    for (std::size_t j = 0; j < eq.size(); ++j) {
      if (eq[i] < 0 || eq[j] < 0) continue;
      const double d = Kd(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      if (d != Ks(eq[i], eq[j])) ++differ;
      if (d != 0.0) ++nonzero;
    }
  CHECK(differ == 0);
  CHECK(nonzero >= min_nonzero);  // not an empty comparison
}

}  // namespace

TEST_CASE("assembly: sparse (recorded pattern, then replayed) equals dense, residual and tangent") {
  const Model m = tube_on_grid();
  const std::vector<NodeState> nodes = initial_nodes(m);
  const BeamPoints points = make_beam_points(m);
  ContactSet contacts(m, nodes);
  int neq = 0;
  const std::vector<int> eq = free_equations(m, neq);
  const AssemblyState state{m, nodes, points, 0.0};
  const double t1 = 1e-3, dt = 1e-3;
  const int n = 6 * static_cast<int>(m.X.size());
  for (const TimeRule::Kind kind : {TimeRule::Kind::Newmark, TimeRule::Kind::QuasiStatic}) {
    const TimeRule rule(kind);  // a rule has its own pattern (the dampers act under Newmark only)
    SparseSink ss;
    ss.eq = &eq;
    ss.neq = neq;
    for (int pass = 0; pass < 3; ++pass) {  // pass 0 records the pattern, the others replay it
      CAPTURE(pass);
      const VectorXd q = increments(m.X.size(), 2e-4, 0.3 * pass);
      MatrixXd Kd = MatrixXd::Zero(n, n);
      DenseSink ds(&Kd);
      VectorXd Rd, Rs, R0;
      assemble(state, rule, contacts, q, t1, dt, false, Rd, &ds);
      CHECK(contacts.closes_deeper_than(0.0));  // pairs in contact at this iterate
      ss.begin();
      assemble(state, rule, contacts, q, t1, dt, false, Rs, &ss);
      ss.finish();
      CHECK_FALSE(ss.mismatch);
      check_same(Kd, Rd, ss, Rs, eq, 300);
      assemble(state, rule, contacts, q, t1, dt, false, R0, nullptr);  // residual without any sink
      CHECK((R0.array() == Rd.array()).all());
    }
  }
  // the mass matrix of the initial acceleration (Sec. 5) into the same pattern
  MatrixXd Md = MatrixXd::Zero(n, n);
  DenseSink ds(&Md);
  VectorXd Rd, Rs;
  const TimeRule rule(TimeRule::Kind::QuasiStatic);
  assemble(state, rule, contacts, VectorXd::Zero(n), 0.0, 1.0, true, Rd, &ds);
  SparseSink ss;
  ss.eq = &eq;
  ss.neq = neq;
  ss.begin();
  assemble(state, rule, contacts, VectorXd::Zero(n), 0.0, 1.0, true, Rs, &ss);
  ss.finish();
  CHECK_FALSE(ss.mismatch);
  check_same(Md, Rd, ss, Rs, eq, 90);
}

TEST_CASE("assembly: a replay out of the recorded order is detected") {
  const std::vector<int> eq = {0, 1, 2};
  SparseSink ss;
  ss.eq = &eq;
  ss.neq = 3;
  ss.begin();
  ss.add(0, 0, 1.0);
  ss.add(1, 2, 2.0);
  ss.add(0, 0, 3.0);
  ss.finish();
  CHECK(MatrixXd(ss.A)(0, 0) == 4.0);
  CHECK(MatrixXd(ss.A)(1, 2) == 2.0);
  ss.begin();  // same order: values replace the recorded ones
  ss.add(0, 0, 5.0);
  ss.add(1, 2, 6.0);
  ss.add(0, 0, 7.0);
  ss.finish();
  CHECK_FALSE(ss.mismatch);
  CHECK(MatrixXd(ss.A)(0, 0) == 12.0);
  ss.begin();  // another order
  ss.add(1, 2, 6.0);
  ss.add(0, 0, 5.0);
  ss.finish();
  CHECK(ss.mismatch);
}
