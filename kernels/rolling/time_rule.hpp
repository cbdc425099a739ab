// Time-integration rule of the rolling Solver, chosen once from SolverOptions: quasi-static load
// stepping (no inertia, time is the load parameter), Newmark trapezoidal (README) or
// the energy-consistent implicit midpoint (R-50..R-52). The assembly and the commit of a step ask
// the rule for its coefficients and updates instead of branching on the integrator themselves.
#pragma once

#include <Eigen/Dense>

#include "kernels/rolling/contact_element.hpp"
#include "kernels/rolling/rotary_inertia.hpp"
#include "kernels/rolling/solver.hpp"
#include "kernels/rolling/time_series.hpp"

namespace rollspec::rolling {

class TimeRule {
 public:
  enum class Kind { QuasiStatic, Newmark, Midpoint };

  explicit TimeRule(Kind kind) : kind_(kind) {}
  static TimeRule from(const SolverOptions& options);

  Kind kind() const { return kind_; }
  // Inertia terms in the residual (the dynamic rules).
  bool inertia() const { return kind_ != Kind::QuasiStatic; }

  // Load multiplier of a step t0 -> t1: the end value, or the step average.
  double load(const TimeSeries& series, double t0, double t1) const {
    return kind_ == Kind::Midpoint ? 0.5 * (series(t0) + series(t1)) : series(t1);
  }

  // d(acceleration)/d(du) of acceleration(): 4/dt^2 or 2/dt^2; 0 without inertia.
  double mass_coefficient(double dt) const {
    return inertia() ? (kind_ == Kind::Midpoint ? 2.0 : 4.0) / (dt * dt) : 0.0;
  }

  // Translational acceleration for the increment du from (v_n, a_n), c2 = mass_coefficient(dt):
  // Newmark a_{n+1} = c2 (du - dt v_n) - a_n; midpoint the step's mean acceleration
  // (v_{n+1} - v_n)/dt = c2 (du - dt v_n).
  Eigen::Vector3d acceleration(double c2, const Eigen::Vector3d& du, double dt, const Eigen::Vector3d& v,
                               const Eigen::Vector3d& a) const {
    return kind_ == Kind::Midpoint ? Eigen::Vector3d(c2 * (du - dt * v)) : Eigen::Vector3d(c2 * (du - dt * v) - a);
  }

  // Inertia pseudo-moment of a rotating point and its tangent: R-32 (Newmark) or R-51 (midpoint).
  RotaryInertiaEval rotary(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn, const Eigen::Vector3d& Wn,
                           const Eigen::Vector3d& An, double dt, const Eigen::Vector3d& alpha,
                           bool want_tangent = true) const;

  // Normal penalty force of plane pairs: end point or discrete gradient.
  NormalForce normal_force() const {
    return kind_ == Kind::Midpoint ? NormalForce::DiscreteGradient : NormalForce::EndPoint;
  }

  // Rough-surface normal dampers act on the Newmark end velocity only.
  bool contact_dampers() const { return kind_ == Kind::Newmark; }

  // Friction force (or moment) of a plane pair whose work over the step is counted: trapezoidal
  // or the end-point value acting over the whole step.
  Eigen::Vector3d friction_for_work(const Eigen::Vector3d& start, const Eigen::Vector3d& end) const {
    return kind_ == Kind::Midpoint ? end : Eigen::Vector3d(0.5 * (start + end));
  }

  // Commit of a node's rates for the converged increment (du, alpha): v, a and the
  // body-frame W, A. Positions and rotations are the caller's.
  void update_rates(NodeState& n, const Eigen::Vector3d& du, const Eigen::Vector3d& alpha, double dt) const;

  // The same for the body-frame rates of a beam mass point (rotation R_n, increment alpha).
  void update_point_rates(const Eigen::Matrix3d& Rn, double dt, const Eigen::Vector3d& alpha, Eigen::Vector3d& W,
                          Eigen::Vector3d& A) const;

 private:
  Kind kind_;
};

}  // namespace rollspec::rolling
