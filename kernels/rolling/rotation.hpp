// Incremental Rodrigues rotation parameters (kernels/README.md D-12, seed 000 Eq. 1-4, 23-25).
// Q(a) = I + g (A + A^2/2), A = skew(a), g = 4/(4 + a.a); spatial spin of Q(a(t)):
// w = Xi(a) a_dot, Xi = g (I + A/2). Generic (templated) versions act on 3-vectors of any
// scalar (doubles or jets), the Eigen versions are for the hand-derived contact tangent.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

namespace rollspec::rolling {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

inline double rodrigues_g(const Eigen::Vector3d& a) { return 4.0 / (4.0 + a.squaredNorm()); }

// Q(a), D-12.
inline Eigen::Matrix3d rodrigues_q(const Eigen::Vector3d& a) {
  const Eigen::Matrix3d A = skew(a);
  return Eigen::Matrix3d::Identity() + rodrigues_g(a) * (A + 0.5 * A * A);
}

// Xi(a) = g (I + A/2), seed 000 Eq. 3: w = Xi a_dot, delta_theta = Xi delta_a.
inline Eigen::Matrix3d rodrigues_xi(const Eigen::Vector3d& a) {
  return rodrigues_g(a) * (Eigen::Matrix3d::Identity() + 0.5 * skew(a));
}

// d(Xi^T m)/da at fixed m: the operator O1 of seed 000 Eq. 25 (README Eq. R-7).
inline Eigen::Matrix3d d_xi_transpose_m(const Eigen::Vector3d& a, const Eigen::Vector3d& m) {
  const double g = rodrigues_g(a);
  const Eigen::Vector3d xtm = rodrigues_xi(a).transpose() * m;
  return 0.5 * g * skew(m) - 0.5 * g * xtm * a.transpose();
}

// Rodrigues vector a = 2 tan(theta/2) e of a rotation vector theta e.
inline Eigen::Vector3d rodrigues_from_rotation_vector(const Eigen::Vector3d& theta) {
  const double t = theta.norm();
  if (t < 1e-300) return Eigen::Vector3d::Zero();
  return (2.0 * std::tan(0.5 * t) / t) * theta;
}

// ---- generic 3-vector algebra for jets ----------------------------------------------
template <class T>
using Vec3 = std::array<T, 3>;

template <class T>
inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
inline Vec3<T> add(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class T>
inline Vec3<T> sub(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T, class S>
inline Vec3<T> scale(const S& c, const Vec3<T>& a) {
  return {c * a[0], c * a[1], c * a[2]};
}
// M v and M^T v with a double matrix.
template <class T>
inline Vec3<T> mul(const Eigen::Matrix3d& M, const Vec3<T>& v) {
  return {M(0, 0) * v[0] + M(0, 1) * v[1] + M(0, 2) * v[2], M(1, 0) * v[0] + M(1, 1) * v[1] + M(1, 2) * v[2],
          M(2, 0) * v[0] + M(2, 1) * v[1] + M(2, 2) * v[2]};
}
template <class T>
inline Vec3<T> mul_t(const Eigen::Matrix3d& M, const Vec3<T>& v) {
  return {M(0, 0) * v[0] + M(1, 0) * v[1] + M(2, 0) * v[2], M(0, 1) * v[0] + M(1, 1) * v[1] + M(2, 1) * v[2],
          M(0, 2) * v[0] + M(1, 2) * v[1] + M(2, 2) * v[2]};
}

template <class T>
inline T g_of(const Vec3<T>& a) {
  return 4.0 / (4.0 + dot(a, a));
}

// Q(a) v = v + g (a x v + a x (a x v)/2), D-12.
template <class T>
inline Vec3<T> q_apply(const Vec3<T>& a, const Vec3<T>& v) {
  const T g = g_of(a);
  const Vec3<T> av = cross(a, v);
  return add(v, scale(g, add(av, scale(0.5, cross(a, av)))));
}
// Q(a)^T v = v + g (-a x v + a x (a x v)/2).
template <class T>
inline Vec3<T> qt_apply(const Vec3<T>& a, const Vec3<T>& v) {
  const T g = g_of(a);
  const Vec3<T> av = cross(a, v);
  return add(v, scale(g, sub(scale(0.5, cross(a, av)), av)));
}
// Xi(a) v = g (v + a x v / 2), seed 000 Eq. 3.
template <class T>
inline Vec3<T> xi_apply(const Vec3<T>& a, const Vec3<T>& v) {
  return scale(g_of(a), add(v, scale(0.5, cross(a, v))));
}
// Xi(a)^T v = g (v - a x v / 2).
template <class T>
inline Vec3<T> xit_apply(const Vec3<T>& a, const Vec3<T>& v) {
  return scale(g_of(a), sub(v, scale(0.5, cross(a, v))));
}

}  // namespace rollspec::rolling
