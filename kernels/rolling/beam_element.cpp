#include "kernels/rolling/beam_element.hpp"

#include "kernels/rolling/jet.hpp"
#include "kernels/rolling/rotation.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;

void quadratic_shape(double xi, double N[3], double dN[3]) {
  N[0] = 0.5 * xi * (xi - 1.0);
  N[1] = 1.0 - xi * xi;
  N[2] = 0.5 * xi * (xi + 1.0);
  dN[0] = xi - 0.5;
  dN[1] = -2.0 * xi;
  dN[2] = xi + 0.5;
}

namespace {

// Point energy per unit length as a function of z = (x', a, a'), README Eq. R-13.
template <class T>
T point_energy(const BeamSection& s, const BeamStiffPoint& p, const Vec3<T>& xp, const Vec3<T>& a,
               const Vec3<T>& ap) {
  // Gamma = R_n^T Q^T x' - E1
  Vec3<T> G = mul_t(p.R, qt_apply(a, xp));
  G[0] = G[0] - 1.0;
  // K = K_n + R_n^T Q^T Xi a'
  Vec3<T> K = mul_t(p.R, qt_apply(a, xi_apply(a, ap)));
  for (int i = 0; i < 3; ++i) K[i] = K[i] + p.K(i);
  return 0.5 * (s.EA * G[0] * G[0] + s.GA2 * G[1] * G[1] + s.GA3 * G[2] * G[2] +
                s.GJ * K[0] * K[0] + s.EI2 * K[1] * K[1] + s.EI3 * K[2] * K[2]);
}

}  // namespace

BeamStrain beam_point_strain(const BeamStiffPoint& p, const std::array<Vector3d, 3>& x,
                             const std::array<Vector3d, 3>& alpha) {
  double N[3], dN[3];
  quadratic_shape(p.xi, N, dN);
  Vector3d xp = Vector3d::Zero(), a = Vector3d::Zero(), ap = Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    xp += dN[k] / p.jac * x[k];
    a += N[k] * alpha[k];
    ap += dN[k] / p.jac * alpha[k];
  }
  BeamStrain st;
  const Matrix3d Q = rodrigues_q(a);
  st.R = Q * p.R;
  st.Gamma = st.R.transpose() * xp - Vector3d::UnitX();
  st.K = p.K + p.R.transpose() * Q.transpose() * rodrigues_xi(a) * ap;
  return st;
}

BeamElementEval beam_element_internal(const BeamSection& s, const std::array<BeamStiffPoint, 2>& gp,
                                      const std::array<Vector3d, 3>& x,
                                      const std::array<Vector3d, 3>& alpha, bool want_tangent) {
  BeamElementEval out;
  using J9 = Jet2<9>;
  for (const BeamStiffPoint& p : gp) {
    double N[3], dN[3];
    quadratic_shape(p.xi, N, dN);
    // B maps the 18 element DOFs to z = (x', a, a'), 9 x 18.
    Eigen::Matrix<double, 9, 18> B = Eigen::Matrix<double, 9, 18>::Zero();
    Vector3d xp = Vector3d::Zero(), a = Vector3d::Zero(), ap = Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      const double d = dN[k] / p.jac;
      xp += d * x[k];
      a += N[k] * alpha[k];
      ap += d * alpha[k];
      B.block<3, 3>(0, 6 * k) = d * Matrix3d::Identity();
      B.block<3, 3>(3, 6 * k + 3) = N[k] * Matrix3d::Identity();
      B.block<3, 3>(6, 6 * k + 3) = d * Matrix3d::Identity();
    }
    Vec3<J9> jxp, ja, jap;
    for (int i = 0; i < 3; ++i) {
      jxp[i] = J9::variable(xp(i), i);
      ja[i] = J9::variable(a(i), 3 + i);
      jap[i] = J9::variable(ap(i), 6 + i);
    }
    const J9 e = point_energy(s, p, jxp, ja, jap);
    const double w = p.weight * p.jac;
    Eigen::Matrix<double, 9, 1> grad;
    for (int i = 0; i < 9; ++i) grad(i) = e.g[i];
    out.energy += w * e.v;
    out.force += w * B.transpose() * grad;
    if (want_tangent) {
      Eigen::Matrix<double, 9, 9> H;
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) H(i, j) = e.h[i * 9 + j];
      out.tangent += w * B.transpose() * H * B;
    }
  }
  return out;
}

}  // namespace rollspec::rolling
