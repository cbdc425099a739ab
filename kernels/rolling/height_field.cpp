#include "kernels/rolling/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollspec::rolling {

namespace {

// Catmull-Rom weights of samples i-1, i, i+1, i+2 at t in [0, 1] and their first and
// second derivatives in t.
inline __attribute__((always_inline)) void catmull_rom(double t, double w[4], double dw[4], double ddw[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (-t2 + t3);
  dw[0] = 0.5 * (-1.0 + 4.0 * t - 3.0 * t2);
  dw[1] = 0.5 * (-10.0 * t + 9.0 * t2);
  dw[2] = 0.5 * (1.0 + 8.0 * t - 9.0 * t2);
  dw[3] = 0.5 * (-2.0 * t + 3.0 * t2);
  ddw[0] = 0.5 * (4.0 - 6.0 * t);
  ddw[1] = 0.5 * (-10.0 + 18.0 * t);
  ddw[2] = 0.5 * (8.0 - 18.0 * t);
  ddw[3] = 0.5 * (-2.0 + 6.0 * t);
}

// Cell index, local t and whether s lies inside the table (outside: clamped, zero slope).
struct Axis {
  int i = 0;
  double t = 0.0;
  bool inside = true;
};
inline __attribute__((always_inline)) Axis locate(double s, double s0, double ds, int n) {
  Axis a;
  if (n < 2) {
    a.inside = false;
    return a;
  }
  double u = (s - s0) / ds;
  if (u < 0.0 || u > n - 1) {
    a.inside = false;
    u = std::clamp(u, 0.0, double(n - 1));
  }
  a.i = std::min(static_cast<int>(u), n - 2);  // u >= 0 here: truncation = floor
  a.t = u - a.i;
  return a;
}

}  // namespace

// Two-lane vectors (GCC/Clang vector extension; SSE2 on x86-64, plain code elsewhere).
typedef double Lanes2 __attribute__((vector_size(16)));

namespace {
// Where s falls on each axis and the Catmull-Rom weights of its four taps and their first and second
// derivatives (along s2 a single tap of weight 1 on a line field): the same for the fast and the plain sums.
struct Taps {
  Axis a1, a2;
  bool grid = false;
  double w1[4], d1[4], dd1[4], w2[4] = {0, 1, 0, 0}, d2[4] = {0, 0, 0, 0}, dd2[4] = {0, 0, 0, 0};
};

Taps taps(const HeightField& f, const Eigen::Vector2d& s) {
  Taps t;
  t.a1 = locate(s(0), f.s1_0, f.ds1, f.n1);
  t.grid = f.n2 > 1;
  if (t.grid) t.a2 = locate(s(1), f.s2_0, f.ds2, f.n2);
  catmull_rom(t.a1.t, t.w1, t.d1, t.dd1);
  if (t.grid) catmull_rom(t.a2.t, t.w2, t.d2, t.dd2);
  return t;
}

// The s2 scaling, the symmetric Hessian and the flat continuation where s is clamped: the same for
// the fast and the plain tap sums.
void finish_sample(HeightSample& out, const HeightField& f, bool grid, const Axis& a1, const Axis& a2) {
  if (grid) {
    out.grad(1) /= f.ds2;
    out.hess(0, 1) /= f.ds1 * f.ds2;
    out.hess(1, 1) /= f.ds2 * f.ds2;
  }
  out.hess(1, 0) = out.hess(0, 1);
  if (!a1.inside) {  // clamped: flat continuation along s1
    out.grad(0) = 0.0;
    out.hess.row(0).setZero();
    out.hess.col(0).setZero();
  }
  if (grid && !a2.inside) {
    out.grad(1) = 0.0;
    out.hess.row(1).setZero();
    out.hess.col(1).setZero();
  }
}
}  // namespace

// The six tap sums in three pairs (h, h_1), (h_2, h_11), (h_12, h_22): per sum the same products
// (a_i b_j) v in the same order as the plain loop of sample_height_reference, so the same bits.
HeightSample sample_height(const HeightField& f, const Eigen::Vector2d& s) {
  const Taps t = taps(f, s);
  const Axis &a1 = t.a1, &a2 = t.a2;
  const bool grid = t.grid;
  const double *w1 = t.w1, *d1 = t.d1, *dd1 = t.dd1, *w2 = t.w2, *d2 = t.d2, *dd2 = t.dd2;
  Lanes2 P[4][3], Q[4][3];
  for (int i = 0; i < 4; ++i) {
    P[i][0] = Lanes2{w1[i], d1[i]};
    P[i][1] = Lanes2{w1[i], dd1[i]};
    P[i][2] = Lanes2{d1[i], w1[i]};
    Q[i][0] = Lanes2{w2[i], w2[i]};
    Q[i][1] = Lanes2{d2[i], w2[i]};
    Q[i][2] = Lanes2{d2[i], dd2[i]};
  }
  Lanes2 acc[3] = {Lanes2{0.0, 0.0}, Lanes2{0.0, 0.0}, Lanes2{0.0, 0.0}};
  const int j0 = grid ? -1 : 0, j1 = grid ? 2 : 0;
  const bool interior = a1.i >= 1 && a1.i + 2 <= f.n1 - 1 && (!grid || (a2.i >= 1 && a2.i + 2 <= f.n2 - 1));
  for (int j = j0; j <= j1; ++j) {
    double v[4];
    if (interior) {  // away from the edges the samples are read without clamping (the same values)
      const double* row = f.h.data() + static_cast<std::size_t>(a2.i + j) * static_cast<std::size_t>(f.n1) +
                          static_cast<std::size_t>(a1.i - 1);
      for (int i = 0; i < 4; ++i) v[i] = row[i];
    } else {
      const std::size_t i2 = static_cast<std::size_t>(std::clamp(a2.i + j, 0, f.n2 - 1));
      for (int i = 0; i < 4; ++i)
        v[i] =
            f.h[i2 * static_cast<std::size_t>(f.n1) + static_cast<std::size_t>(std::clamp(a1.i + i - 1, 0, f.n1 - 1))];
    }
    const Lanes2* q = Q[j + 1];
    for (int i = 0; i < 4; ++i) {
      const Lanes2 vv = {v[i], v[i]};
      for (int k = 0; k < 3; ++k) acc[k] += P[i][k] * q[k] * vv;
    }
  }
  HeightSample out;
  out.h = acc[0][0];
  out.grad(0) = acc[0][1] / f.ds1;
  out.grad(1) = acc[1][0];
  out.hess(0, 0) = acc[1][1] / (f.ds1 * f.ds1);
  out.hess(0, 1) = acc[2][0];
  out.hess(1, 1) = acc[2][1];
  finish_sample(out, f, grid, a1, a2);
  return out;
}

// The plain tap loop, one sum after another: the reference of sample_height (tests).
HeightSample sample_height_reference(const HeightField& f, const Eigen::Vector2d& s) {
  HeightSample out;
  const Taps t = taps(f, s);
  const Axis &a1 = t.a1, &a2 = t.a2;
  const bool grid = t.grid;
  const double *w1 = t.w1, *d1 = t.d1, *dd1 = t.dd1, *w2 = t.w2, *d2 = t.d2, *dd2 = t.dd2;
  auto at = [&](int i1, int i2) {
    i1 = std::clamp(i1, 0, f.n1 - 1);
    i2 = std::clamp(i2, 0, f.n2 - 1);
    return f.h[static_cast<std::size_t>(i2) * static_cast<std::size_t>(f.n1) + static_cast<std::size_t>(i1)];
  };
  const int j0 = grid ? -1 : 0, j1 = grid ? 2 : 0;
  // away from the edges the 4 x 4 samples are read without clamping (the same values, same order)
  const bool interior = a1.i >= 1 && a1.i + 2 <= f.n1 - 1 && (!grid || (a2.i >= 1 && a2.i + 2 <= f.n2 - 1));
  for (int j = j0; j <= j1; ++j) {
    const double* row = interior ? f.h.data() + static_cast<std::size_t>(a2.i + j) * static_cast<std::size_t>(f.n1) +
                                       static_cast<std::size_t>(a1.i - 1)
                                 : nullptr;
    for (int i = -1; i <= 2; ++i) {
      const double v = interior ? row[i + 1] : at(a1.i + i, a2.i + j);
      const int ii = i + 1, jj = j + 1;
      out.h += w1[ii] * w2[jj] * v;
      out.grad(0) += d1[ii] * w2[jj] * v;
      out.grad(1) += w1[ii] * d2[jj] * v;
      out.hess(0, 0) += dd1[ii] * w2[jj] * v;
      out.hess(0, 1) += d1[ii] * d2[jj] * v;
      out.hess(1, 1) += w1[ii] * dd2[jj] * v;
    }
  }
  out.grad(0) /= f.ds1;
  out.hess(0, 0) /= f.ds1 * f.ds1;
  finish_sample(out, f, grid, a1, a2);
  return out;
}

namespace {
ContactValidity single_point_contact(const HeightField& f, double radius, bool screen) {
  ContactValidity v;
  const bool grid = f.n2 > 1;
  const int m1 = 2 * f.n1 - 1, m2 = grid ? 2 * f.n2 - 1 : 1;
  for (int j = 0; j < m2; ++j)
    for (int i = 0; i < m1; ++i) {
      // samples and cell midpoints; a sample on a cell boundary is taken from the cell on its left
      const Eigen::Vector2d s(f.s1_0 + 0.5 * i * f.ds1, grid ? f.s2_0 + 0.5 * j * f.ds2 : 0.0);
      const HeightSample hs = sample_height(f, s);
      const double g2 = 1.0 + hs.grad.squaredNorm();
      double k = 0.0;
      if (grid) {
        // Gershgorin bound on the larger eigenvalue, widened by the solver's round-off (a few eps
        // of |H|): a point whose bound cannot beat the largest curvature so far is passed over
        // without the eigensolver (the same maximum and place, bit for bit)
        const double a = hs.hess(0, 0), b = hs.hess(1, 1), c = std::abs(hs.hess(0, 1));
        const double bound = std::max(a, b) + c + 1e-12 * (std::abs(a) + std::abs(b) + 2.0 * c);
        if (screen && !(bound > v.max_concave_curvature)) continue;  // k <= bound / sqrt(g2) <= bound (g2 >= 1)
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(hs.hess);
        k = es.eigenvalues()(1) / std::sqrt(g2);
      } else {
        k = hs.hess(0, 0) / (g2 * std::sqrt(g2));
      }
      if (k > v.max_concave_curvature) {
        v.max_concave_curvature = k;
        v.where = s;
      }
    }
  v.radius_limit =
      v.max_concave_curvature > 0.0 ? 1.0 / v.max_concave_curvature : std::numeric_limits<double>::infinity();
  v.valid = radius * v.max_concave_curvature < 1.0;
  return v;
}
}  // namespace

ContactValidity check_single_point_contact(const HeightField& f, double radius) {
  return single_point_contact(f, radius, true);
}

ContactValidity check_single_point_contact_reference(const HeightField& f, double radius) {
  return single_point_contact(f, radius, false);
}

}  // namespace rollspec::rolling
