#include "kernels/rolling/contact_element.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/rolling/rotation.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Plane make_plane(const Vector3d& point, const Vector3d& normal) {
  Plane p;
  p.point = point;
  p.normal = normal.normalized();
  // t1: the global axis least aligned with n, projected; t2 = n x t1.
  Vector3d e = Vector3d::UnitX();
  if (std::abs(p.normal.x()) > 0.9) e = Vector3d::UnitY();
  p.t1 = (e - e.dot(p.normal) * p.normal).normalized();
  p.t2 = p.normal.cross(p.t1);
  return p;
}

PenaltyGradient penalty_discrete_gradient(double eps_n, double g0, double g1) {
  // V(g) = eps_n <-g>^2 / 2, V'(g) = eps_n min(g, 0), V'' = eps_n on g < 0 (README R-50)
  auto V = [&](double g) { return g < 0.0 ? 0.5 * eps_n * g * g : 0.0; };
  auto dV = [&](double g) { return g < 0.0 ? eps_n * g : 0.0; };
  PenaltyGradient d;
  const double dg = g1 - g0;
  if (std::abs(dg) <= 1e-12 * (std::abs(g0) + std::abs(g1)) || dg == 0.0) {
    const double gm = 0.5 * (g0 + g1);  // limit: V'(g_mid), derivative V''/2
    d.value = dV(gm);
    d.derivative = gm < 0.0 ? 0.5 * eps_n : 0.0;
    return d;
  }
  d.value = (V(g1) - V(g0)) / dg;
  d.derivative = (dV(g1) - d.value) / dg;
  return d;
}

ContactEval evaluate_contact(const Plane& plane, const ContactLaw& law, const ContactState& state,
                             const Vector3d& x_start, const Vector3d& x, const Vector3d& alpha,
                             NormalForce normal_force, bool want_tangent) {
  ContactEval e;
  const Vector3d& n = plane.normal;
  const Matrix3d P = Matrix3d::Identity() - n * n.transpose();  // t1 t1^T + t2 t2^T
  const double r = law.radius;
  const double rr = law.rolling ? r : 0.0;  // "no rolling": r = 0 in gap and moment

  // Reset on separation (seed 000 end of Sec. 3): a contact that was open at the start of
  // the step starts from the projection of the node, with no accumulated slip.
  const Vector3d xf0 = state.active ? state.x_f : Vector3d(x_start - (x_start - plane.point).dot(n) * n);
  const Vector3d gst0 = state.active ? state.g_st : Vector3d::Zero();

  const Vector3d Qn = rodrigues_q(alpha) * n;
  const Vector3d x_f = xf0 + rr * P * (Qn - n);  // (D-13), seed 000 Eq. 7
  e.g_n = (x - plane.point).dot(n) - r;          // (D-14), seed 000 Eq. 11 (x_f lies on the plane)
  e.point = x - r * n;
  // touching (g_n = 0) counts as closed, so that a predictor from a touching state sees
  // the normal penalty stiffness
  // normal force magnitude along n: end point eps_n <-g_n> (R-22) or discrete gradient
  double fn = e.g_n <= 0.0 ? law.eps_n * (-e.g_n) : 0.0, dfn = law.eps_n;  // dfn = -d fn / d g_n
  if (normal_force == NormalForce::DiscreteGradient) {
    const double g0 = (x_start - plane.point).dot(n) - r;
    const PenaltyGradient dg = penalty_discrete_gradient(law.eps_n, g0, e.g_n);
    fn = -dg.value;
    dfn = dg.derivative;
  }
  if (!(e.g_n <= 0.0)) {  // open at the end: no friction, state reset at commit
    if (fn != 0.0) {      // discrete gradient of a step that opens the contact
      e.normal_force = fn;
      e.force = fn * n;
      e.residual.head<3>() = -e.force;
      e.tangent.block<3, 3>(0, 0) = dfn * n * n.transpose();
    }
    return e;
  }
  e.active = true;

  const Vector3d gt = P * (x - x_f) - gst0;  // (D-14), seed 000 Eq. 8-10, elastic gap
  e.g_t = gt;
  const Vector3d ftry = -law.eps_t * gt;  // seed 000 Eq. 12
  const double fmax = law.mu * law.eps_n * (-e.g_n);

  const Matrix3d Xi = rodrigues_xi(alpha);
  // d g_t / d a = r P skew(Q n) Xi  (README Eq. R-21; d(Qn) = -skew(Qn) Xi da)
  const Matrix3d dgt_da = want_tangent ? Matrix3d(rr * P * skew(Qn) * Xi) : Matrix3d::Zero();

  Vector3d f;
  Matrix3d df_dx = Matrix3d::Zero(), df_da = Matrix3d::Zero();
  const double ntry = ftry.norm();
  if (!(fmax > 0.0)) {  // frictionless (mu = 0): free tangential motion
    f.setZero();
    df_dx.setZero();
    df_da.setZero();
    e.slip = ntry > 0.0;
    e.next.g_st = gst0 + gt;  // all tangential motion is slip, elastic gap stays zero
  } else if (ntry <= fmax) {  // stick
    f = ftry;
    if (want_tangent) {
      df_dx = -law.eps_t * P;
      df_da = -law.eps_t * dgt_da;
    }
    e.next.g_st = gst0;
    e.tangential_energy = 0.5 * ntry * ntry / law.eps_t;
  } else {  // slip: return mapping, seed 000 Eq. 13-16 and 32
    e.slip = true;
    const double ngt = gt.norm();
    const Vector3d tau = gt / ngt;  // n_T, Eq. 15
    f = -fmax * tau;
    if (want_tangent) {
      const Matrix3d Pt = (Matrix3d::Identity() - tau * tau.transpose()) / ngt;  // Eq. 38
      df_dx = law.mu * law.eps_n * tau * n.transpose() - fmax * Pt * P;
      df_da = -fmax * Pt * dgt_da;
    }
    const double dslip = (ntry - fmax) / law.eps_t;  // Eq. 14
    e.next.g_st = gst0 + dslip * tau;                // Eq. 13
    e.dissipation = fmax * dslip;
    e.tangential_energy = 0.5 * fmax * fmax / law.eps_t;
  }
  e.friction = f;
  e.normal_force = fn;
  e.force = fn * n + f;
  e.moment = -rr * n.cross(f);  // (C - x_o) x f with C - x_o = -r n (seed 000 Eq. 33)
  e.next.active = true;
  e.next.x_f = x_f;

  const Vector3d m = Xi.transpose() * e.moment;  // pseudo-moment, seed 000 Eq. 6
  e.residual.head<3>() = -e.force;
  e.residual.tail<3>() = -m;
  if (!want_tangent) return e;  // residual-only assembly (R-44a): the tangent stays zero

  const Matrix3d dF_dx = -dfn * n * n.transpose() + df_dx;
  const Matrix3d& dF_da = df_da;
  const Matrix3d dM_dx = -rr * skew(n) * df_dx;
  const Matrix3d dM_da = -rr * skew(n) * df_da;
  e.tangent.block<3, 3>(0, 0) = -dF_dx;
  e.tangent.block<3, 3>(0, 3) = -dF_da;
  e.tangent.block<3, 3>(3, 0) = -Xi.transpose() * dM_dx;
  e.tangent.block<3, 3>(3, 3) = -(Xi.transpose() * dM_da + d_xi_transpose_m(alpha, e.moment));
  return e;
}

}  // namespace rollspec::rolling
