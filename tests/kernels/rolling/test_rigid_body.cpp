// Rotary inertia with the material-frame Newmark scheme on Rodrigues increments (README
// R-31..R-33): torque-free symmetric top against the closed-form body-frame precession, and
// conservation of spatial angular momentum and kinetic energy for an asymmetric body.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/solver.hpp"

using namespace rollspec::rolling;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
Model free_body(const Matrix3d& J, const Vector3d& w0_spatial) {
  Model m;
  const int n = m.add_node(Vector3d::Zero());
  m.bodies.push_back(RigidBody{n, 1.0, J});
  m.w0 = {w0_spatial};
  return m;
}
}  // namespace

TEST_CASE("torque-free symmetric top: body-frame precession at (J3 - J1)/J1 * W3") {
  const Matrix3d J = Vector3d(1.0, 1.0, 2.0).asDiagonal();
  const double a = 0.5, c = 4.0;  // W0 = (a, 0, c), precession rate c
  SolverOptions o;
  o.force_tol = 1e-12;
  RunOptions ro;
  ro.dt = 1e-3;
  ro.t_end = 2.0;
  const History h = run(free_body(J, Vector3d(a, 0, c)), o, ro);
  REQUIRE(h.completed);
  double err = 0.0;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    const Vector3d W = h.rotation[k][0].transpose() * h.angular_velocity[k][0];
    const double t = h.time[k];
    const Vector3d We(a * std::cos(c * t), a * std::sin(c * t), c);
    err = std::max(err, (W - We).norm() / a);
  }
  MESSAGE("max body angular velocity error / a over 2 s: " << err);
  CHECK(err < 1e-4);  // O(dt^2) phase error
}

TEST_CASE("torque-free asymmetric body: angular momentum and energy conserved") {
  const Matrix3d J = Vector3d(1.0, 2.0, 3.0).asDiagonal();
  SolverOptions o;
  o.force_tol = 1e-12;
  RunOptions ro;
  ro.dt = 1e-3;
  ro.t_end = 5.0;
  const History h = run(free_body(J, Vector3d(0.3, 0.2, 4.0)), o, ro);
  REQUIRE(h.completed);
  auto L = [&](std::size_t k) {
    const Matrix3d& R = h.rotation[k][0];
    return Vector3d(R * J * R.transpose() * h.angular_velocity[k][0]);
  };
  double dl = 0, de = 0;
  const Vector3d L0 = L(0);
  const double E0 = h.energy[0].kinetic;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    dl = std::max(dl, (L(k) - L0).norm() / L0.norm());
    de = std::max(de, std::abs(h.energy[k].kinetic - E0) / E0);
  }
  MESSAGE("max relative drift over 5 s: angular momentum " << dl << ", kinetic energy " << de);
  CHECK(dl < 1e-6);
  CHECK(de < 1e-6);
}
