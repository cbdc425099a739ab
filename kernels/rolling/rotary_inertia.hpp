// Inertia of a rotating point (rigid body node or beam mass point) with Newmark
// trapezoidal (beta = 1/4, gamma = 1/2) applied to the material incremental Rodrigues
// vector b = R_n^T a (README Eq. R-30..R-33):
//   W_{n+1} = 2 b/dt - W_n,  A_{n+1} = 4 (b - dt W_n)/dt^2 - A_n     (body-frame vectors)
//   inertia pseudo-moment  r(a) = Xi(a)^T Q(a) R_n (J A + W x J W) = Xi(a) R_n (J A + W x J W)
// with its tangent written out (R-33a); the Jet2<3> versions are kept as references.
// This is the material-frame Newmark scheme of Simo & Vu-Quoc (1988, CMAME 66:125-161,
// Sec. 4) with the Cayley/Rodrigues map in place of the exponential map, as used for
// Rodrigues-parameter beams by Gay Neto, Pimenta & Martins (2013) [seed 000 ref. 12].
#pragma once

#include <Eigen/Dense>

namespace rollspec::rolling {

struct RotaryInertiaEval {
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();  // pseudo-moment conjugate to a
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();   // d residual / d a
  Eigen::Vector3d W = Eigen::Vector3d::Zero();         // body angular velocity at t_{n+1}
  Eigen::Vector3d A = Eigen::Vector3d::Zero();         // body angular acceleration at t_{n+1}
};

// want_tangent = false: the tangent is left zero (residual-only assembly, R-44a), the rest the same bits.
RotaryInertiaEval rotary_inertia(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn, const Eigen::Vector3d& Wn,
                                 const Eigen::Vector3d& An, double dt, const Eigen::Vector3d& alpha,
                                 bool want_tangent = true);

// Newmark update of the body angular velocity/acceleration for a converged increment a.
void rotary_newmark_update(const Eigen::Matrix3d& Rn, double dt, const Eigen::Vector3d& alpha, Eigen::Vector3d& W,
                           Eigen::Vector3d& A);

// Energy-consistent (implicit midpoint) variant, README R-51: with b = R_n^T a,
//   W_{n+1} = 2 b/dt - W_n,  W_m = b/dt = (W_n + W_{n+1})/2,
//   h = J (W_{n+1} - W_n)/dt + W_m x J W_m,  r(a) = Xi(a)^T Q(a) R_n h,
// so that T_{n+1} - T_n = b . h  (= a . m for r = Xi^T m): kinetic energy changes exactly by
// the work a . m of the applied spatial moment m. A is set to (W_{n+1} - W_n)/dt.
RotaryInertiaEval rotary_inertia_midpoint(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn,
                                          const Eigen::Vector3d& Wn, double dt, const Eigen::Vector3d& alpha,
                                          bool want_tangent = true);
// The same with Jet2<3> (R-33): the plain references of the analytic tangents above (R-33a).
RotaryInertiaEval rotary_inertia_reference(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn,
                                           const Eigen::Vector3d& Wn, const Eigen::Vector3d& An, double dt,
                                           const Eigen::Vector3d& alpha);
RotaryInertiaEval rotary_inertia_midpoint_reference(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Rn,
                                                    const Eigen::Vector3d& Wn, double dt, const Eigen::Vector3d& alpha);

void rotary_midpoint_update(const Eigen::Matrix3d& Rn, double dt, const Eigen::Vector3d& alpha, Eigen::Vector3d& W,
                            Eigen::Vector3d& A);

}  // namespace rollspec::rolling
