#pragma once
// Undeformed gap of a ball on a rough flat, effective modulus (kernels/README.md (contact), D-6, D-7).
#include <vector>

#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

// 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2   (D-6). Throws std::invalid_argument unless E > 0 and
// −1 < ν ≤ 0.5.
double effective_modulus(double e1, double nu1, double e2, double nu2);

enum class BallShape {
  Sphere,      // exact: z(r) = R − sqrt(R² − r²)  (cells with r ≥ R get z = R, never touched)
  Paraboloid,  // Hertz's approximation z(r) = r²/(2R): the continuum Hertz solution is exact for it
};

// Undeformed gap s_i = z_ball(r_i) − h_i (README Eq. 5) between a ball of radius R whose lowest
// point touches the plane z = 0 at (centre_x, centre_y) and a rough flat with heights h_i (m, up
// positive, x-fastest on `grid`, cell centres as in Grid). An empty `heights` means a smooth flat.
// Rough on rough: the gap depends on the two height fields only through their sum, so pass the
// composite heights h_flat + h_ball (h_ball measured outward from the ball, i.e. downward), see
// composite_heights. The approach w of ContactSolver is measured from this reference: the gap
// under load is g_i = s_i − w + u_i (D-7); first contact is at w = min_i s_i.
std::vector<double> ball_gap(const Grid& grid, double radius, const std::vector<double>& heights,
                             BallShape shape = BallShape::Sphere, double centre_x = 0.0, double centre_y = 0.0);

// Composite height field h1 + h2 of two rough surfaces (same grid), for rough-on-rough contact.
std::vector<double> composite_heights(const std::vector<double>& h1, const std::vector<double>& h2);

}  // namespace rollspec::contact
