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
T point_energy(const BeamSection& s, const BeamStiffPoint& p, const Vec3<T>& xp, const Vec3<T>& a, const Vec3<T>& ap) {
  // Gamma = R_n^T Q^T x' - E1
  Vec3<T> G = mul_t(p.R, qt_apply(a, xp));
  G[0] = G[0] - 1.0;
  // K = K_n + R_n^T Q^T Xi a'
  Vec3<T> K = mul_t(p.R, qt_apply(a, xi_apply(a, ap)));
  for (int i = 0; i < 3; ++i) K[i] = K[i] + p.K(i);
  return 0.5 * (s.EA * G[0] * G[0] + s.GA2 * G[1] * G[1] + s.GA3 * G[2] * G[2] + s.GJ * K[0] * K[0] +
                s.EI2 * K[1] * K[1] + s.EI3 * K[2] * K[2]);
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

// Reference oracle: the point energy as one scalar function of the 9 point variables,
// differentiated twice by Jet2<9> (slow, obvious).
PointEnergy beam_point_energy_reference(const BeamSection& s, const BeamStiffPoint& p,
                                        const Eigen::Matrix<double, 9, 1>& z) {
  using J9 = Jet2<9>;
  Vec3<J9> jxp, ja, jap;
  for (int i = 0; i < 3; ++i) {
    jxp[i] = J9::variable(z(i), i);
    ja[i] = J9::variable(z(3 + i), 3 + i);
    jap[i] = J9::variable(z(6 + i), 6 + i);
  }
  const J9 e = point_energy(s, p, jxp, ja, jap);
  PointEnergy out;
  out.value = e.v;
  for (int i = 0; i < 9; ++i) {
    out.grad(i) = e.g[i];
    for (int j = 0; j < 9; ++j) out.hess(i, j) = e.h[i * 9 + j];
  }
  return out;
}

// Jet path (README R-14): every strain is bilinear, s_i = v_i . phi_i(a) with
//   Gamma_i = (Q r_i) . x' - delta_i1,   K_i = K_n,i + (Xi^T Q r_i) . a',   r_i = R_n e_i,
// so only the six 3-vectors phi_i(a) need first and second derivatives, with Jet2<3>. Kept as
// the plain reference of the analytic path below.
PointEnergy beam_point_energy_jet(const BeamSection& s, const BeamStiffPoint& p, const Eigen::Matrix<double, 9, 1>& z) {
  using J3 = Jet2<3>;
  Vec3<J3> a;
  for (int i = 0; i < 3; ++i) a[i] = J3::variable(z(3 + i), i);
  const double c[6] = {s.EA, s.GA2, s.GA3, s.GJ, s.EI2, s.EI3};
  PointEnergy out;
  out.grad.setZero();
  out.hess.setZero();
  out.value = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3<J3> ri{J3(p.R(0, i)), J3(p.R(1, i)), J3(p.R(2, i))};
    const Vec3<J3> d = q_apply(a, ri);
    const Vec3<J3> b = xit_apply(a, d);
    for (int kind = 0; kind < 2; ++kind) {  // 0: Gamma_i (v = x'), 1: K_i (v = a')
      const Vec3<J3>& phi = kind == 0 ? d : b;
      const int off = kind == 0 ? 0 : 6;
      const double ci = c[3 * kind + i];
      const Eigen::Vector3d v = z.segment<3>(off);
      double si = 0.0;
      Eigen::Vector3d phiv, gal = Eigen::Vector3d::Zero();  // ds/dv, ds/da
      Eigen::Matrix3d Jp, Haa = Eigen::Matrix3d::Zero();    // d phi_k/d a_j, d2 s/da2
      for (int k = 0; k < 3; ++k) {
        si += phi[k].v * v(k);
        phiv(k) = phi[k].v;
        for (int j = 0; j < 3; ++j) {
          Jp(k, j) = phi[k].g[j];
          gal(j) += v(k) * phi[k].g[j];
          for (int l = 0; l < 3; ++l) Haa(j, l) += v(k) * phi[k].h[j * 3 + l];
        }
      }
      si += kind == 0 ? (i == 0 ? -1.0 : 0.0) : p.K(i);
      out.value += 0.5 * ci * si * si;
      Eigen::Matrix<double, 9, 1> g = Eigen::Matrix<double, 9, 1>::Zero();
      g.segment<3>(off) = phiv;
      g.segment<3>(3) = gal;
      out.grad += ci * si * g;
      out.hess += ci * g * g.transpose();
      out.hess.block<3, 3>(3, 3) += ci * si * Haa;
      out.hess.block<3, 3>(off, 3) += ci * si * Jp;
      out.hess.block<3, 3>(3, off) += ci * si * Jp.transpose();
    }
  }
  return out;
}

// Analytic point energy, gradient and Hessian (README R-14a). The Cayley form of Q gives
// Xi^T Q = Xi, so K = K_n + R_n^T Xi^T a' and with R = Q R_n, N = C_N Gamma, M = C_M K,
// n = R_n N, m = R_n M:
//   dGamma/da = G_G = R^T skew(x') Xi,   dK/da = G_K = (g/2) R_n^T (skew(a') - (Xi^T a') a^T)
//   d psi/dx' = R N,  d psi/da = G_G^T N + G_K^T M,  d psi/da' = Xi m
// and the Hessian from d(Q w)/da = -skew(Q w) Xi, d(Xi w)/da = -(g/2)((Xi w) a^T + skew(w))
// and the second derivatives of f1 = x'.Q(a) n, f2 = a'.Xi(a) m at fixed n, m, written with
// g = 4/(4 + a.a), grad g = -(g^2/2) a, hess g = -(g^2/2) I + (g^3/2) a a^T:
//   f1 = x'.n + g h,  h = p.a + a^T S a / 2,  p = n x x',  S = (x' n^T + n x'^T)/2 - (x'.n) I
//   f2 = g (a'.m + q.a),  q = (m x a')/2.
PointEnergy beam_point_energy(const BeamSection& s, const BeamStiffPoint& p, const Eigen::Matrix<double, 9, 1>& z,
                              bool want_hess) {
  const Vector3d xp = z.segment<3>(0), a = z.segment<3>(3), ap = z.segment<3>(6);
  const double g = rodrigues_g(a);
  const Matrix3d Xi = rodrigues_xi(a);
  const Matrix3d R = rodrigues_q(a) * p.R;
  const Matrix3d XR = Xi * p.R;  // columns Xi r_i
  const Vector3d CN(s.EA, s.GA2, s.GA3), CM(s.GJ, s.EI2, s.EI3);
  Vector3d Gam = R.transpose() * xp;
  Gam(0) -= 1.0;
  const Vector3d K = p.K + XR.transpose() * ap;
  const Vector3d N = CN.cwiseProduct(Gam), M = CM.cwiseProduct(K);
  const Vector3d n = p.R * N, m = p.R * M;
  const Matrix3d GG = R.transpose() * skew(xp) * Xi;
  const Matrix3d GK = (0.5 * g) * p.R.transpose() * (skew(ap) - (Xi.transpose() * ap) * a.transpose());
  PointEnergy out;
  out.value = 0.5 * (Gam.dot(N) + K.dot(M));
  out.grad.segment<3>(0) = R * N;
  out.grad.segment<3>(3) = GG.transpose() * N + GK.transpose() * M;
  out.grad.segment<3>(6) = Xi * m;
  if (!want_hess) return out;  // hess stays zero; value and gradient as with it
  // second derivatives of g
  const Vector3d dg = -0.5 * g * g * a;
  const Matrix3d ddg = -0.5 * g * g * Matrix3d::Identity() + 0.5 * g * g * g * a * a.transpose();
  // f1 = x'.Q(a) n
  const Vector3d pv = n.cross(xp);
  const Matrix3d S = 0.5 * (xp * n.transpose() + n * xp.transpose()) - xp.dot(n) * Matrix3d::Identity();
  const double h = pv.dot(a) + 0.5 * a.dot(S * a);
  const Vector3d dh = pv + S * a;
  // f2 = a'.Xi(a) m
  const Vector3d qv = 0.5 * m.cross(ap);
  const double l2 = ap.dot(m) + qv.dot(a);
  const Matrix3d haa = GG.transpose() * CN.asDiagonal() * GG + GK.transpose() * CM.asDiagonal() * GK + h * ddg +
                       dg * dh.transpose() + dh * dg.transpose() + g * S + l2 * ddg + dg * qv.transpose() +
                       qv * dg.transpose();
  const Matrix3d hxa = R * CN.asDiagonal() * GG - skew(R * N) * Xi;
  const Matrix3d hpa = XR * CM.asDiagonal() * GK - (0.5 * g) * ((Xi * m) * a.transpose() + skew(m));
  out.hess.setZero();
  out.hess.block<3, 3>(0, 0) = R * CN.asDiagonal() * R.transpose();
  out.hess.block<3, 3>(6, 6) = XR * CM.asDiagonal() * XR.transpose();
  out.hess.block<3, 3>(3, 3) = 0.5 * (haa + haa.transpose());
  out.hess.block<3, 3>(0, 3) = hxa;
  out.hess.block<3, 3>(3, 0) = hxa.transpose();
  out.hess.block<3, 3>(6, 3) = hpa;
  out.hess.block<3, 3>(3, 6) = hpa.transpose();
  return out;
}

// Element force and tangent with B applied by node (B maps node k's DOFs to z by the scalars
// N_k and dN_k/ds on identity blocks): no 9 x 18 products.
BeamElementEval beam_element_internal(const BeamSection& s, const std::array<BeamStiffPoint, 2>& gp,
                                      const std::array<Vector3d, 3>& x, const std::array<Vector3d, 3>& alpha,
                                      bool want_tangent) {
  BeamElementEval out;
  for (const BeamStiffPoint& p : gp) {
    double N[3], dN[3], d[3];
    quadratic_shape(p.xi, N, dN);
    Vector3d xp = Vector3d::Zero(), a = Vector3d::Zero(), ap = Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      d[k] = dN[k] / p.jac;
      xp += d[k] * x[k];
      a += N[k] * alpha[k];
      ap += d[k] * alpha[k];
    }
    Eigen::Matrix<double, 9, 1> z;
    z << xp, a, ap;
    const PointEnergy e = beam_point_energy(s, p, z, want_tangent);
    const double w = p.weight * p.jac;
    out.energy += w * e.value;
    for (int k = 0; k < 3; ++k) {
      out.force.segment<3>(6 * k) += (w * d[k]) * e.grad.segment<3>(0);
      out.force.segment<3>(6 * k + 3) += w * (N[k] * e.grad.segment<3>(3) + d[k] * e.grad.segment<3>(6));
    }
    if (!want_tangent) continue;
    const Matrix3d Hxx = e.hess.block<3, 3>(0, 0), Hxa = e.hess.block<3, 3>(0, 3), Haa = e.hess.block<3, 3>(3, 3),
                   Hpa = e.hess.block<3, 3>(6, 3), Hpp = e.hess.block<3, 3>(6, 6);
    for (int l = 0; l < 3; ++l) {
      // columns of H B for node l: displacement (d_l x') and rotation (N_l a + d_l a')
      const Matrix3d Cxa = N[l] * Hxa, Caa = N[l] * Haa + d[l] * Hpa.transpose(), Cpa = N[l] * Hpa + d[l] * Hpp;
      for (int k = 0; k < 3; ++k) {
        out.tangent.block<3, 3>(6 * k, 6 * l) += (w * d[k] * d[l]) * Hxx;
        out.tangent.block<3, 3>(6 * k, 6 * l + 3) += (w * d[k]) * Cxa;
        out.tangent.block<3, 3>(6 * k + 3, 6 * l) += (w * d[l]) * (N[k] * Hxa.transpose());
        out.tangent.block<3, 3>(6 * k + 3, 6 * l + 3) += w * (N[k] * Caa + d[k] * Cpa);
      }
    }
  }
  return out;
}

// Reference of the element (B^T grad, B^T hess B with the Jet2<3> point path), for tests.
BeamElementEval beam_element_internal_reference(const BeamSection& s, const std::array<BeamStiffPoint, 2>& gp,
                                                const std::array<Vector3d, 3>& x, const std::array<Vector3d, 3>& alpha,
                                                bool want_tangent) {
  BeamElementEval out;
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
    Eigen::Matrix<double, 9, 1> z;
    z << xp, a, ap;
    const PointEnergy e = beam_point_energy_jet(s, p, z);
    const double w = p.weight * p.jac;
    out.energy += w * e.value;
    out.force += w * B.transpose() * e.grad;
    if (want_tangent) out.tangent += w * B.transpose() * e.hess * B;
  }
  return out;
}

}  // namespace rollspec::rolling
