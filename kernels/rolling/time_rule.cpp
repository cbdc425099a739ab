#include "kernels/rolling/time_rule.hpp"

namespace rollspec::rolling {

TimeRule TimeRule::from(const SolverOptions& options) {
  if (options.analysis == Analysis::QuasiStatic) return TimeRule(Kind::QuasiStatic);
  return TimeRule(options.integrator == Integrator::EnergyConsistent ? Kind::Midpoint : Kind::Newmark);
}

RotaryInertiaEval TimeRule::rotary(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn, const Eigen::Vector3d& Wn,
                                   const Eigen::Vector3d& An, double dt, const Eigen::Vector3d& alpha,
                                   bool want_tangent) const {
  return kind_ == Kind::Midpoint ? rotary_inertia_midpoint(J, Rn, Wn, dt, alpha, want_tangent)
                                 : rotary_inertia(J, Rn, Wn, An, dt, alpha, want_tangent);
}

void TimeRule::update_rates(NodeState& n, const Eigen::Vector3d& du, const Eigen::Vector3d& alpha, double dt) const {
  const double c2 = mass_coefficient(dt);
  if (kind_ == Kind::Midpoint) {  // v_{n+1} = 2 du/dt - v_n, a = mean acceleration of the step
    n.a = acceleration(c2, du, dt, n.v, n.a);
    n.v = 2.0 / dt * du - n.v;
  } else if (kind_ == Kind::Newmark) {
    const Eigen::Vector3d a1 = acceleration(c2, du, dt, n.v, n.a);
    n.v += 0.5 * dt * (n.a + a1);
    n.a = a1;
  }
  update_point_rates(n.R, dt, alpha, n.W, n.A);
}

void TimeRule::update_point_rates(const Eigen::Matrix3d& Rn, double dt, const Eigen::Vector3d& alpha,
                                  Eigen::Vector3d& W, Eigen::Vector3d& A) const {
  if (kind_ == Kind::Midpoint) rotary_midpoint_update(Rn, dt, alpha, W, A);
  if (kind_ == Kind::Newmark) rotary_newmark_update(Rn, dt, alpha, W, A);
}

}  // namespace rollspec::rolling
