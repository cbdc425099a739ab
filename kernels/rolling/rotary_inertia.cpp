#include "kernels/rolling/rotary_inertia.hpp"

#include "kernels/rolling/jet.hpp"
#include "kernels/rolling/rotation.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// r(a) = Xi^T Q R_n h(b) = Xi R_n h(b), b = R_n^T a (Xi^T Q = Xi for the Cayley form of Q), and
//   dr/da = -(g/2)((Xi w) a^T + skew(w)) + Xi R_n (dh/db) R_n^T,  w = R_n h    (R-33a)
// with dh/db = cA J + cW (skew(W) J - skew(J W)) for h = J A + W x J W, dA/db = cA, dW/db = cW.
RotaryInertiaEval rotary_analytic(const Matrix3d& J, const Matrix3d& Rn, const Vector3d& alpha, const Vector3d& W,
                                  const Vector3d& A, const Vector3d& Wg, double cA, double cW, bool want_tangent) {
  const Vector3d JWg = J * Wg;
  const Vector3d h = J * A + Wg.cross(JWg);
  const Vector3d w = Rn * h;
  const Matrix3d Xi = rodrigues_xi(alpha);
  RotaryInertiaEval out;
  out.residual = Xi * w;
  out.W = W;
  out.A = A;
  if (!want_tangent) return out;  // residual-only assembly (R-44a): the tangent stays zero
  const double g = rodrigues_g(alpha);
  const Matrix3d XR = Xi * Rn;
  const Matrix3d dh = cA * J + cW * (skew(Wg) * J - skew(JWg));
  out.tangent = XR * dh * Rn.transpose() - (0.5 * g) * (out.residual * alpha.transpose() + skew(w));
  return out;
}

// The references' residual r(a) = Xi^T Q R_n h (R-33a) and its tangent, read off the jets of a, with the
// angular velocity W and acceleration A it was formed from.
RotaryInertiaEval jet_residual(const Vec3<Jet2<3>>& a, const Matrix3d& Rn, const Vec3<Jet2<3>>& h,
                               const Vec3<Jet2<3>>& W, const Vec3<Jet2<3>>& A) {
  const Vec3<Jet2<3>> r = xit_apply(a, q_apply(a, mul(Rn, h)));
  RotaryInertiaEval out;
  for (int i = 0; i < 3; ++i) {
    out.residual(i) = r[i].v;
    out.W(i) = W[i].v;
    out.A(i) = A[i].v;
    for (int j = 0; j < 3; ++j) out.tangent(i, j) = r[i].g[j];
  }
  return out;
}

}  // namespace

RotaryInertiaEval rotary_inertia(const Matrix3d& J, const Matrix3d& Rn, const Vector3d& Wn, const Vector3d& An,
                                 double dt, const Vector3d& alpha, bool want_tangent) {
  const Vector3d b = Rn.transpose() * alpha;
  const Vector3d W = (2.0 / dt) * b - Wn;
  const Vector3d A = (4.0 / (dt * dt)) * (b - dt * Wn) - An;
  return rotary_analytic(J, Rn, alpha, W, A, W, 4.0 / (dt * dt), 2.0 / dt, want_tangent);
}

RotaryInertiaEval rotary_inertia_midpoint(const Matrix3d& J, const Matrix3d& Rn, const Vector3d& Wn, double dt,
                                          const Vector3d& alpha, bool want_tangent) {
  const Vector3d b = Rn.transpose() * alpha;
  const Vector3d W = (2.0 / dt) * b - Wn;
  const Vector3d Wm = (1.0 / dt) * b;
  const Vector3d D = (2.0 / (dt * dt)) * (b - dt * Wn);  // (W_{n+1} - W_n)/dt, R-51
  return rotary_analytic(J, Rn, alpha, W, D, Wm, 2.0 / (dt * dt), 1.0 / dt, want_tangent);
}

RotaryInertiaEval rotary_inertia_reference(const Matrix3d& J, const Matrix3d& Rn, const Vector3d& Wn,
                                           const Vector3d& An, double dt, const Vector3d& alpha) {
  using J3 = Jet2<3>;
  Vec3<J3> a;
  for (int i = 0; i < 3; ++i) a[i] = J3::variable(alpha(i), i);
  const Vec3<J3> b = mul_t(Rn, a);  // material incremental Rodrigues vector
  Vec3<J3> W, A;
  for (int i = 0; i < 3; ++i) {
    W[i] = (2.0 / dt) * b[i] - Wn(i);
    A[i] = (4.0 / (dt * dt)) * (b[i] - dt * Wn(i)) - An(i);
  }
  const Vec3<J3> h = add(mul(J, A), cross(W, mul(J, W)));  // Euler: J A + W x J W
  return jet_residual(a, Rn, h, W, A);
}

void rotary_newmark_update(const Matrix3d& Rn, double dt, const Vector3d& alpha, Vector3d& W, Vector3d& A) {
  const Vector3d b = Rn.transpose() * alpha;
  const Vector3d A1 = 4.0 / (dt * dt) * (b - dt * W) - A;
  W = 2.0 / dt * b - W;
  A = A1;
}

RotaryInertiaEval rotary_inertia_midpoint_reference(const Matrix3d& J, const Matrix3d& Rn, const Vector3d& Wn,
                                                    double dt, const Vector3d& alpha) {
  using J3 = Jet2<3>;
  Vec3<J3> a;
  for (int i = 0; i < 3; ++i) a[i] = J3::variable(alpha(i), i);
  const Vec3<J3> b = mul_t(Rn, a);
  Vec3<J3> W, Wm, D;
  for (int i = 0; i < 3; ++i) {
    W[i] = (2.0 / dt) * b[i] - Wn(i);
    Wm[i] = (1.0 / dt) * b[i];
    D[i] = (2.0 / (dt * dt)) * (b[i] - dt * Wn(i));  // (W_{n+1} - W_n)/dt
  }
  const Vec3<J3> h = add(mul(J, D), cross(Wm, mul(J, Wm)));
  return jet_residual(a, Rn, h, W, D);
}

void rotary_midpoint_update(const Matrix3d& Rn, double dt, const Vector3d& alpha, Vector3d& W, Vector3d& A) {
  const Vector3d b = Rn.transpose() * alpha;
  A = 2.0 / (dt * dt) * (b - dt * W);
  W = 2.0 / dt * b - W;
}

}  // namespace rollspec::rolling
