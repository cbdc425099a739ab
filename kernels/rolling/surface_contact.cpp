#include "kernels/rolling/surface_contact.hpp"

#include <cmath>

namespace rollspec::rolling {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

SurfaceContactEval evaluate_surface_contact(const HeightField& f, const SurfaceContactLaw& law, const Vector3d& x,
                                            const Vector2d* start, const HeightSample* at_start, bool want_tangent) {
  SurfaceContactEval e;
  const Plane& b = f.base;
  const Vector3d y0 = x - b.point;
  const Vector2d xi(y0.dot(b.t1), y0.dot(b.t2));
  const double zeta = y0.dot(b.normal);
  const bool grid = f.n2 > 1;
  // closest point: grad_s D = (s - xi) - (zeta - h) grad h = 0,
  // H = I + grad h grad h^T - (zeta - h) Hess h
  const double cell = grid ? std::min(f.ds1, f.ds2) : f.ds1;
  Vector2d s = xi;
  if (start && std::isfinite((*start)(0)) && std::isfinite((*start)(1)) && (*start - xi).norm() <= 4.0 * cell) {
    s = *start;
    if (!grid) s(1) = xi(1);  // a line profile: s2 follows the centre exactly
  }
  HeightSample hs = at_start && start && s == *start ? *at_start : sample_height(f, s);
  e.converged = false;
  for (int it = 0; it < 60; ++it) {
    Vector2d G = (s - xi) - (zeta - hs.h) * hs.grad;
    Matrix2d H = Matrix2d::Identity() + hs.grad * hs.grad.transpose() - (zeta - hs.h) * hs.hess;
    if (!grid) {
      G(1) = 0.0;
      H.row(1).setZero();
      H.col(1).setZero();
      H(1, 1) = 1.0;
    }
    Vector2d d;
    // smallest eigenvalue of the symmetric 2 x 2 H in closed form
    const double mean = 0.5 * (H(0, 0) + H(1, 1)), half = 0.5 * (H(0, 0) - H(1, 1));
    const double lambda_min = mean - std::sqrt(half * half + H(0, 1) * H(0, 1));
    if (lambda_min > 1e-12)
      d = -H.ldlt().solve(G);
    else
      d = -G;  // not a minimum yet: descend
    const double dn = d.norm();
    if (dn > cell) d *= cell / dn;  // at most one cell per iteration
    s += d;
    hs = sample_height(f, s);
    // converged at round-off of the coordinates (length scale: cell, |s|, |zeta|)
    if (d.norm() <= 1e-13 * (cell + s.lpNorm<Eigen::Infinity>() + std::abs(zeta))) {
      e.converged = true;
      break;
    }
  }
  e.s = s;
  e.sample = hs;
  e.point = b.point + s(0) * b.t1 + s(1) * b.t2 + hs.h * b.normal;
  const Vector3d y = x - e.point;
  const double dist = y.norm();
  // geometric normal (-grad h, 1), used when the centre lies on the surface
  const Vector3d nu_s = (b.normal - hs.grad(0) * b.t1 - hs.grad(1) * b.t2).normalized();
  const double side = (zeta - hs.h) >= 0.0 ? 1.0 : -1.0;
  e.normal = dist > 1e-14 ? Vector3d(side * y / dist) : nu_s;
  e.g_n = side * dist - law.radius;
  if (!(e.g_n <= 0.0)) return e;
  e.active = true;
  e.force = law.eps_n * (-e.g_n) * e.normal;
  if (!want_tangent) return e;  // residual-only assembly (R-44a): the tangent stays zero
  // d2g/dx2 = (I - S_s H^-1 S_s^T)/d with S_s = [t1 + h_1 n, t2 + h_2 n]
  Eigen::Matrix<double, 3, 2> Ss;
  Ss.col(0) = b.t1 + hs.grad(0) * b.normal;
  Ss.col(1) = b.t2 + hs.grad(1) * b.normal;
  Matrix2d H = Matrix2d::Identity() + hs.grad * hs.grad.transpose() - (zeta - hs.h) * hs.hess;
  // (I - nu nu^T)(I - S_s H^-1 S_s^T) = I - nu nu^T - S_s H^-1 S_s^T since nu is normal to S_s
  Matrix3d Hg = Matrix3d::Identity() - e.normal * e.normal.transpose();
  if (grid) {
    Hg -= Ss * H.inverse() * Ss.transpose();
  } else {  // s2 = xi2 follows x exactly: only the t1 direction is a surface coordinate
    Hg -= Ss.col(0) * Ss.col(0).transpose() / H(0, 0) + b.t2 * b.t2.transpose();
  }
  Hg /= side * dist;
  e.tangent = law.eps_n * (e.normal * e.normal.transpose() + e.g_n * Hg);
  return e;
}

}  // namespace rollspec::rolling
