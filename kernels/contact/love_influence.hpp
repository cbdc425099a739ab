#pragma once
// Love's closed-form influence coefficient of a uniformly loaded rectangle (kernels/README.md D-6).
#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

// Surface displacement at (x, y) of a half-space pair with effective modulus E* (1/E* convention
// of D-6) under unit uniform pressure on the rectangle |x'| ≤ a, |y'| ≤ b (Love 1929;
// Johnson, Contact Mechanics, Eq. 3.96), README Eq. (2):
//   u = 1/(π E*) Σ_corners ± G(x ∓ a, y ∓ b),   G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|).
// G differs from the textbook X ln(Y + r) + Y ln(X + r) by terms in X or Y alone, which cancel in
// the corner sum; the asinh form does not cancel catastrophically for negative X or Y.
double love_displacement(double x, double y, double a, double b, double e_star);

// Coefficient C(ox, oy): displacement at a cell centre from unit pressure on a cell whose centre
// is ox cells along x and oy cells along y away (cells dx × dy).
double love_coefficient(long ox, long oy, double dx, double dy, double e_star);

}  // namespace rollspec::contact
