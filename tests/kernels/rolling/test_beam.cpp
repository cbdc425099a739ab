// Geometrically exact beam (README Sec. 3): tangent against finite differences, quadratic
// Newton convergence, cantilever pressed on a frictionless plane against 3 E I D / L^3, and
// the cantilever rolled into a full circle by an end moment 2 pi E I / L.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "kernels/rolling/beam_element.hpp"
#include "kernels/rolling/rotary_inertia.hpp"
#include "kernels/rolling/rotation.hpp"
#include "kernels/rolling/solver.hpp"
#include "tangent_check.hpp"

using namespace rollspec::rolling;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {
const double kPi = 3.14159265358979323846;

BeamSection given_section(double EI, double L) {
  BeamSection s;
  s.EA = 1e4 * EI / (L * L) * 100;
  s.GA2 = s.GA3 = 0.5 * s.EA;
  s.EI2 = s.EI3 = EI;
  s.GJ = 0.8 * EI;
  s.rhoA = 2.0;
  s.rhoJ1 = 0.02;
  s.rhoI2 = s.rhoI3 = 0.01;
  s.outer_radius = 0.05;
  return s;
}
}  // namespace

TEST_CASE("beam + inertia + load + contact tangent = central differences of the residual") {
  for (const bool dynamic : {false, true}) {
    Model m;
    BeamSection s = given_section(50.0, 2.0);
    s.GA3 = 0.3 * s.EA;  // distinct constants so that every term shows
    s.EI3 = 70.0;
    m.sections.push_back(s);
    const std::vector<int> ids =
        add_straight_beam(m, Vector3d::Zero(), Vector3d(2.0, 0.3, -0.1), 2, 0, Vector3d(0.1, 1.0, 0.2));
    m.sections[0].rhoA = 0.2;
    m.gravity = Vector3d(0.3, -0.2, -9.81);
    m.gravity_series = TimeSeries::ramp(0.0, 0.05);  // load steps, so quasi-static Newton converges
    for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids[0], d, 0.0, TimeSeries::constant()});
    m.loads.push_back(
        NodalLoad{ids[4], Vector3d(0.1, -0.2, 0.3), Vector3d(0.4, 0.5, -0.6), TimeSeries::ramp(0.0, 0.05)});
    m.bodies.push_back(RigidBody{ids[2], 0.3, Vector3d(0.2, 0.3, 0.4).asDiagonal()});
    m.planes.push_back(make_plane(Vector3d(0, 0, -0.06), Vector3d(0.05, 0.02, 1.0)));
    m.contacts.push_back(ContactPair{ids[3], 0, ContactLaw{0.05, 0.3, 1e5, 1e4, true}});
    SolverOptions o;
    o.analysis = dynamic ? Analysis::Dynamic : Analysis::QuasiStatic;
    o.force_tol = 1e-6;
    Solver S(m, o);
    for (int k = 1; k <= 5; ++k) REQUIRE(S.advance(0.01 * k).converged);  // non-trivial committed state
    // a trial increment with finite rotations
    VectorXd q = VectorXd::Zero(6 * static_cast<long>(m.X.size()));
    for (long i = 6; i < q.size(); ++i) q(i) = (i % 6 < 3 ? 0.01 : 0.15) * std::sin(1.7 * double(i) + 0.3);
    const test::TangentCheck c = test::tangent_check(S, q, 0.06, 0.01, 1e-6);
    const Eigen::MatrixXd &K = c.k, &Kfd = c.k_fd;
    const double err = c.error;
    MESSAGE(std::string(dynamic ? "dynamic" : "quasi-static")
            << " tangent rel. error " << err << " (max |K| " << K.cwiseAbs().maxCoeff() << ")");
    CHECK(err < 1e-6);
    // the same test restricted to the beam-only block of an interior node pair
    CHECK((K.block(6, 6, 12, 12) - Kfd.block(6, 6, 12, 12)).cwiseAbs().maxCoeff() <
          1e-6 * K.block(6, 6, 12, 12).cwiseAbs().maxCoeff());
  }
}

TEST_CASE("large rotation: cantilever rolled into a full circle by M = 2 pi EI / L") {
  const double L = 10.0, EI = 100.0;
  Model m;
  m.sections.push_back(given_section(EI, L));
  const std::vector<int> ids = add_straight_beam(m, Vector3d::Zero(), Vector3d(L, 0, 0), 20, 0);
  for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids[0], d, 0.0, TimeSeries::constant()});
  m.loads.push_back(NodalLoad{ids.back(), Vector3d::Zero(), Vector3d(0, 0, 2 * kPi * EI / L), TimeSeries::ramp(0, 1)});
  SolverOptions o;
  o.analysis = Analysis::QuasiStatic;
  o.force_tol = 1e-8;
  Solver S(m, o);
  int its = 0;
  for (int k = 1; k <= 40; ++k) {
    const StepReport rep = S.advance(k / 40.0);
    REQUIRE(rep.converged);
    its += rep.iterations;
  }
  const Vector3d tip = S.nodes()[ids.back()].x;
  const Vector3d mid = S.nodes()[ids[20]].x;
  const Eigen::AngleAxisd aa(S.nodes()[ids.back()].R);
  MESSAGE("tip " << tip.transpose() << " |tip - root|/L = " << tip.norm() / L << ", mid " << mid.transpose()
                 << " (exact 0, " << L / kPi << "), tip rotation angle " << aa.angle() << ", Newton its " << its);
  CHECK(tip.norm() < 0.005 * L);
  CHECK(std::abs(mid.y() - L / kPi) < 0.005 * L);  // diameter L/pi
  CHECK(std::abs(mid.x()) < 0.005 * L);
  CHECK(aa.angle() < 0.005 * 2 * kPi);  // rotated by 2 pi: back to the identity
}

TEST_CASE("Newton converges quadratically near the solution (3D cantilever, force + torque)") {
  const double L = 10.0, EI = 100.0;
  Model m;
  BeamSection s = given_section(EI, L);
  s.EA = 1e4;
  s.GA2 = s.GA3 = 5e3;
  m.sections.push_back(s);
  const std::vector<int> ids = add_straight_beam(m, Vector3d::Zero(), Vector3d(L, 0, 0), 4, 0);
  m.loads.push_back(NodalLoad{ids.back(), Vector3d(0, 0.1, 0.15), Vector3d(0.2, 0, 0), TimeSeries::constant()});
  SolverOptions o;
  o.analysis = Analysis::QuasiStatic;
  Solver S(m, o);
  const long n = 6 * static_cast<long>(m.X.size()), nf = n - 6;  // node 0 clamped
  auto res = [&](const VectorXd& qf, Eigen::MatrixXd* Kf) {
    VectorXd q = VectorXd::Zero(n), r;
    q.tail(nf) = qf;
    Eigen::MatrixXd K;
    S.residual_and_tangent(q, 1.0, 1.0, r, Kf ? &K : nullptr);
    if (Kf) *Kf = K.bottomRightCorner(nf, nf);
    return VectorXd(r.tail(nf));
  };
  // solution q* by Newton from the undeformed state
  VectorXd qs = VectorXd::Zero(nf);
  Eigen::MatrixXd K;
  std::string hist;
  for (int it = 0; it < 20; ++it) {
    const VectorXd r = res(qs, &K);
    hist += std::to_string(r.norm()) + " ";
    qs -= K.fullPivLu().solve(r);
  }
  MESSAGE("Newton from the undeformed state, |r|: " << hist);
  REQUIRE(res(qs, nullptr).norm() < 1e-9);
  // one Newton step from q* + delta v: |r_1| must scale with |r_0|^2
  VectorXd v(nf);
  for (long i = 0; i < nf; ++i) v(i) = std::sin(2.3 * double(i) + 0.7);
  std::vector<double> r0, r1;
  for (const double d : {1e-2, 1e-3, 1e-4}) {
    const VectorXd q0 = qs + d * v;
    const VectorXd r = res(q0, &K);
    const VectorXd q1 = q0 - K.fullPivLu().solve(r);
    r0.push_back(r.norm());
    r1.push_back(res(q1, nullptr).norm());
    MESSAGE("delta " << d << ": |r0| " << r0.back() << ", |r1| " << r1.back() << ", |r1|/|r0|^2 "
                     << r1.back() / (r0.back() * r0.back()));
  }
  for (std::size_t k = 0; k + 1 < r0.size(); ++k) {
    const double order = std::log(r1[k] / r1[k + 1]) / std::log(r0[k] / r0[k + 1]);
    MESSAGE("convergence order from deltas " << k << "," << k + 1 << ": " << order);
    CHECK(order > 1.9);  // an inconsistent tangent gives order 1
  }
}

TEST_CASE("frictionless cantilever pressed on a plane: tip force = 3 EI D / L^3 (20 elements)") {
  const double L = 10.0, Dsec = 0.3, E = 1e7, D = 0.05;
  Model m;
  m.sections.push_back(circular_section(E, 0.0, 1.0, Dsec));
  const double r = 0.5 * Dsec, EI = m.sections[0].EI2;
  const std::vector<int> ids = add_straight_beam(m, Vector3d::Zero(), Vector3d(L, 0, 0), 20, 0);
  // the plane touches the tip sphere; the clamped root is lowered by D
  m.planes.push_back(make_plane(Vector3d(0, 0, -r), Vector3d::UnitZ()));
  m.contacts.push_back(ContactPair{ids.back(), 0, ContactLaw{r, 0.0, 1e7, 0.0, true}});
  for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids[0], d, d == 2 ? -D : 0.0, TimeSeries::ramp(0, 1)});
  SolverOptions o;
  o.analysis = Analysis::QuasiStatic;
  o.force_tol = 1e-9;
  Solver S(m, o);
  for (int k = 1; k <= 4; ++k) REQUIRE(S.advance(k / 4.0).converged);
  const double F = S.contacts()[0].force.z();
  const double Fexact = 3.0 * EI * D / (L * L * L);
  MESSAGE("tip contact force " << F << " vs 3EI D/L^3 = " << Fexact << ", rel " << std::abs(F / Fexact - 1)
                               << "; root reaction z " << S.reactions()[2]);
  CHECK(std::abs(F / Fexact - 1.0) < 0.01);
  CHECK(std::abs(S.reactions()[2] + F) < 1e-6 * F);  // equilibrium
}

TEST_CASE("beam point energy: fast bilinear path = Jet2<9> reference oracle") {
  BeamSection s = given_section(50.0, 2.0);
  s.GA3 = 0.3 * s.EA;
  s.EI3 = 70.0;
  BeamStiffPoint p;
  p.R = rodrigues_q(Vector3d(0.3, -0.5, 0.2));
  p.K = Vector3d(0.1, -0.2, 0.05);
  Eigen::Matrix<double, 9, 1> z;
  z << 0.9, 0.2, -0.1, 0.4, -0.3, 0.6, 0.05, -0.02, 0.08;
  const PointEnergy f = beam_point_energy(s, p, z), r = beam_point_energy_reference(s, p, z);
  CHECK(std::abs(f.value - r.value) < 1e-13 * std::abs(r.value));
  CHECK((f.grad - r.grad).cwiseAbs().maxCoeff() < 1e-12 * r.grad.cwiseAbs().maxCoeff());
  CHECK((f.hess - r.hess).cwiseAbs().maxCoeff() < 1e-12 * r.hess.cwiseAbs().maxCoeff());
  CHECK((f.hess - f.hess.transpose()).cwiseAbs().maxCoeff() < 1e-12 * f.hess.cwiseAbs().maxCoeff());
}

// Largest entry difference over the largest entry of the reference.
template <class A, class B>
double rel_diff(const A& a, const B& ref) {
  return (a - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
}

TEST_CASE("beam element: analytic force and tangent (R-14a) = the Jet2<3> reference on random states") {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&](double scale) { return Vector3d(scale * u(rng), scale * u(rng), scale * u(rng)); };
  double worst_f = 0.0, worst_k = 0.0, worst_p = 0.0;
  for (int trial = 0; trial < 40; ++trial) {
    BeamSection s;
    s.EA = 1e8 * (1.5 + u(rng));
    s.GA2 = 0.4e8 * (1.5 + u(rng));
    s.GA3 = 0.3e8 * (1.5 + u(rng));
    s.GJ = 2e3 * (1.5 + u(rng));
    s.EI2 = 1e3 * (1.5 + u(rng));
    s.EI3 = 1.2e3 * (1.5 + u(rng));
    // element of length 0.25 along a random direction, committed frames and curvatures random;
    // increments up to 2.4 in |a| (a rotation of 100 degrees) in the large-rotation trials
    const double big = trial % 2 == 0 ? 1.4 : 0.05;
    std::array<BeamStiffPoint, 2> gp;
    for (int k = 0; k < 2; ++k) {
      gp[k].xi = k == 0 ? -1.0 / std::sqrt(3.0) : 1.0 / std::sqrt(3.0);
      gp[k].weight = 1.0;
      gp[k].jac = 0.125 * (1.0 + 0.1 * u(rng));
      gp[k].R = rodrigues_q(vec(3.0));
      gp[k].K = vec(2.0);
    }
    const Vector3d dir = rodrigues_q(vec(3.0)).col(0);
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      x[k] = 0.125 * (k - 1) * dir + vec(0.01);
      a[k] = vec(big);
    }
    const BeamElementEval f = beam_element_internal(s, gp, x, a, true);
    const BeamElementEval r = beam_element_internal_reference(s, gp, x, a, true);
    worst_f = std::max(worst_f, rel_diff(f.force, r.force));
    worst_k = std::max(worst_k, rel_diff(f.tangent, r.tangent));
    CHECK(std::abs(f.energy - r.energy) <= 1e-12 * std::abs(r.energy));
    Eigen::Matrix<double, 9, 1> z;
    z << vec(1.0), a[0], vec(big);
    const PointEnergy pa = beam_point_energy(s, gp[0], z), pj = beam_point_energy_jet(s, gp[0], z);
    worst_p = std::max({worst_p, rel_diff(pa.grad, pj.grad), rel_diff(pa.hess, pj.hess)});
    // without the Hessian (residual-only assembly, R-44a): the same value and gradient bits
    const PointEnergy pg = beam_point_energy(s, gp[0], z, false);
    CHECK(pg.value == pa.value);
    CHECK(pg.grad == pa.grad);
    CHECK(pg.hess.isZero(0.0));
    const BeamElementEval fg = beam_element_internal(s, gp, x, a, false);
    CHECK(fg.force == f.force);
    CHECK(fg.energy == f.energy);
  }
  MESSAGE("analytic vs Jet2<3>: force " << worst_f << ", tangent " << worst_k << ", point grad/hess " << worst_p);
  CHECK(worst_f < 1e-10);
  CHECK(worst_k < 1e-10);
  CHECK(worst_p < 1e-10);
}

TEST_CASE("rotary inertia: analytic tangent (R-33a) = the Jet2<3> reference, Newmark and midpoint") {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&](double scale) { return Vector3d(scale * u(rng), scale * u(rng), scale * u(rng)); };
  double worst = 0.0;
  for (int trial = 0; trial < 40; ++trial) {
    Matrix3d J = Vector3d(2.0 + u(rng), 1.0 + 0.5 * u(rng), 1.0 + 0.5 * u(rng)).asDiagonal();
    const Matrix3d Rn = rodrigues_q(vec(3.0));
    const Vector3d Wn = vec(50.0), An = vec(1e3), alpha = vec(trial % 2 == 0 ? 1.5 : 1e-3);
    const double dt = trial % 2 == 0 ? 1e-2 : 2.5e-5;
    const RotaryInertiaEval a = rotary_inertia(J, Rn, Wn, An, dt, alpha),
                            r = rotary_inertia_reference(J, Rn, Wn, An, dt, alpha);
    const RotaryInertiaEval am = rotary_inertia_midpoint(J, Rn, Wn, dt, alpha),
                            rm = rotary_inertia_midpoint_reference(J, Rn, Wn, dt, alpha);
    worst = std::max({worst, rel_diff(a.residual, r.residual), rel_diff(a.tangent, r.tangent),
                      rel_diff(am.residual, rm.residual), rel_diff(am.tangent, rm.tangent)});
    CHECK(rel_diff(a.W, r.W) < 1e-14);
    CHECK(rel_diff(a.A, r.A) < 1e-14);
    CHECK(rel_diff(am.A, rm.A) < 1e-14);
    // without the tangent (residual-only assembly, R-44a): the same residual and rates, bit for bit
    const RotaryInertiaEval a0 = rotary_inertia(J, Rn, Wn, An, dt, alpha, false),
                            am0 = rotary_inertia_midpoint(J, Rn, Wn, dt, alpha, false);
    CHECK(a0.residual == a.residual);
    CHECK(a0.W == a.W);
    CHECK(a0.A == a.A);
    CHECK(am0.residual == am.residual);
    CHECK(am0.A == am.A);
    CHECK(a0.tangent.isZero(0.0));
  }
  MESSAGE("rotary inertia analytic vs Jet2<3>: " << worst);
  CHECK(worst < 1e-10);
}

TEST_CASE("step cutting: a load step too large for Newton is halved and reaches the same state") {
  const double L = 10.0, EI = 100.0;
  auto make = [&]() {
    Model m;
    m.sections.push_back(given_section(EI, L));
    const std::vector<int> ids = add_straight_beam(m, Vector3d::Zero(), Vector3d(L, 0, 0), 10, 0);
    for (int d = 0; d < 6; ++d) m.imposed.push_back(ImposedDof{ids[0], d, 0.0, TimeSeries::constant()});
    m.loads.push_back(NodalLoad{ids.back(), Vector3d(0, 1.0, 1.5), Vector3d(2.0, 0, 0), TimeSeries::ramp(0, 1)});
    return m;
  };
  SolverOptions o;
  o.analysis = Analysis::QuasiStatic;
  o.force_tol = 1e-7;
  o.max_cuts = 0;
  Solver one(make(), o);
  CHECK(!one.advance(1.0).converged);  // pure Newton diverges in one step
  o.max_cuts = 10;
  Solver cut(make(), o);
  const StepReport rep = cut.advance(1.0);
  REQUIRE(rep.converged);
  Solver ref(make(), o);
  for (int k = 1; k <= 20; ++k) REQUIRE(ref.advance(k / 20.0).converged);
  const Vector3d a = cut.nodes().back().x, b = ref.nodes().back().x;
  MESSAGE("cuts " << rep.cuts << ", tip " << a.transpose() << " vs 20 steps " << b.transpose());
  CHECK(rep.cuts > 0);
  CHECK((a - b).norm() < 1e-6 * L);  // path-independent elastic solution
}
