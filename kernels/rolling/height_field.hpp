// Rigid rough surface = plane + height field (README Sec. 10, R-60..R-62). Heights h on a
// regular grid in the plane's tangent coordinates s = ((x - p).t1, (x - p).t2); n2 = 1 is a
// line profile h(s1) (constant along t2). Interpolation: Catmull-Rom cubic per direction
// (tensor product for grids), C1, interpolating, with analytic gradient and Hessian inside a
// cell; outside the table the height is held at the clamped coordinate (zero slope).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "kernels/rolling/contact_element.hpp"

namespace rollspec::rolling {

struct HeightField {
  Plane base;                    // reference plane; heights along base.normal
  double s1_0 = 0.0, ds1 = 1.0;  // first sample coordinate and spacing along t1
  double s2_0 = 0.0, ds2 = 1.0;  // ... along t2 (unused when n2 == 1)
  int n1 = 0, n2 = 1;            // samples per direction; n2 == 1: line profile
  std::vector<double> h;         // heights, h[i2 * n1 + i1]
};

struct HeightSample {
  double h = 0.0;
  Eigen::Vector2d grad = Eigen::Vector2d::Zero();  // dh/ds
  Eigen::Matrix2d hess = Eigen::Matrix2d::Zero();  // d2h/ds2 (within a cell)
};

// Interpolated height and derivatives at tangent coordinates s.
HeightSample sample_height(const HeightField& f, const Eigen::Vector2d& s);
// The plain loop over the taps, one sum after another; sample_height gives the same bits (tests).
HeightSample sample_height_reference(const HeightField& f, const Eigen::Vector2d& s);

// Line profile h(s1) sampled from a function on [s_begin, s_end] with n samples.
template <class F>
HeightField line_height_field(const Plane& base, double s_begin, double s_end, int n, F&& h) {
  HeightField f;
  f.base = base;
  f.s1_0 = s_begin;
  f.ds1 = (s_end - s_begin) / (n - 1);
  f.n1 = n;
  f.n2 = 1;
  for (int i = 0; i < n; ++i) f.h.push_back(h(s_begin + i * f.ds1));
  return f;
}

// A grid's samples along one tangent direction: the first coordinate, the spacing, the count.
struct GridAxis {
  double s0 = 0.0, ds = 1.0;
  int n = 1;
};

// Grid h(s1, s2) sampled at s1 = s1_0 + i ds1, s2 = s2_0 + j ds2, stored i fastest as HeightField keeps it.
template <class F>
HeightField grid_height_field(const Plane& base, GridAxis a1, GridAxis a2, F&& h) {
  HeightField f;
  f.base = base;
  f.s1_0 = a1.s0, f.ds1 = a1.ds, f.n1 = a1.n;
  f.s2_0 = a2.s0, f.ds2 = a2.ds, f.n2 = a2.n;
  f.h.reserve(static_cast<std::size_t>(a1.n) * static_cast<std::size_t>(a2.n));
  for (int j = 0; j < f.n2; ++j)
    for (int i = 0; i < f.n1; ++i) f.h.push_back(h(f.s1_0 + i * f.ds1, f.s2_0 + j * f.ds2));
  return f;
}

// Single-point contact validity: the sphere of radius r touches the surface at one
// point when it is not sharper than the surface's concave curvature, r * kappa_max < 1, with
// kappa_max the largest concave (valley) normal curvature: h''/(1 + h'^2)^(3/2) for a line,
// the bound lambda_max(Hess h)/sqrt(1 + |grad h|^2) for a grid; evaluated at every sample and
// cell midpoint of the interpolant. Convex parts (peaks) never give two-point contact.
struct ContactValidity {
  double max_concave_curvature = 0.0;
  double radius_limit = 0.0;                        // 1/kappa_max (infinity for a surface without valleys)
  bool valid = true;                                // radius * kappa_max < 1
  Eigen::Vector2d where = Eigen::Vector2d::Zero();  // tangent coordinates of kappa_max
};
ContactValidity check_single_point_contact(const HeightField& f, double radius);
// The same with the eigenvalues of every grid point; check_single_point_contact passes over the
// points whose Gershgorin bound cannot beat the largest curvature so far (the same result, tests).
ContactValidity check_single_point_contact_reference(const HeightField& f, double radius);

}  // namespace rollspec::rolling
