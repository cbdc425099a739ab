#include "kernels/contact/geometry.hpp"

#include <cmath>
#include <stdexcept>

namespace rollspec::contact {

double effective_modulus(double e1, double nu1, double e2, double nu2) {
  if (!(e1 > 0.0) || !(e2 > 0.0) || !(nu1 > -1.0 && nu1 < 0.5 + 1e-12) || !(nu2 > -1.0 && nu2 < 0.5 + 1e-12))
    throw std::invalid_argument("effective_modulus: need E > 0 and -1 < nu <= 0.5");
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

std::vector<double> ball_gap(const Grid& grid, double radius, const std::vector<double>& heights, BallShape shape,
                             double centre_x, double centre_y) {
  check_grid(grid);
  if (!(radius > 0.0)) throw std::invalid_argument("ball_gap: radius must be > 0");
  if (!heights.empty() && heights.size() != grid.size())
    throw std::invalid_argument("ball_gap: heights size != grid size");
  std::vector<double> s(grid.size());
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix) {
      const double rx = grid.x(ix) - centre_x, ry = grid.y(iy) - centre_y;
      const double r2 = rx * rx + ry * ry;
      double z;
      if (shape == BallShape::Paraboloid) {
        z = r2 / (2.0 * radius);
      } else {
        // R − sqrt(R² − r²) = r²/(R + sqrt(R² − r²)): no cancellation for r ≪ R.
        z = r2 < radius * radius ? r2 / (radius + std::sqrt(radius * radius - r2)) : radius;
      }
      const std::size_t i = iy * grid.nx + ix;
      s[i] = z - (heights.empty() ? 0.0 : heights[i]);
    }
  return s;
}

std::vector<double> composite_heights(const std::vector<double>& h1, const std::vector<double>& h2) {
  if (h1.size() != h2.size()) throw std::invalid_argument("composite_heights: sizes differ");
  std::vector<double> h(h1.size());
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = h1[i] + h2[i];
  return h;
}

}  // namespace rollspec::contact
