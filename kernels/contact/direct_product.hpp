#pragma once
// Reference oracle: the half-space product by plain O(N²) summation of Love coefficients.
#include <vector>

#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

// u[i] = Σ_k C(x_i − x_k, y_i − y_k) p[k] with C from love_displacement (README Eq. 1–2), open
// boundary. Slow and obvious; tests compare HalfSpaceOperator (Boundary::Open) with it.
std::vector<double> direct_product(const Grid& grid, double e_star, const std::vector<double>& p);

}  // namespace rollspec::contact
