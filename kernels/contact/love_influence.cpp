#include "kernels/contact/love_influence.hpp"

#include <cmath>
#include <stdexcept>

namespace rollspec::contact {

void check_grid(const Grid& grid) {
  if (grid.nx < 1 || grid.ny < 1 || !(grid.dx > 0.0) || !(grid.dy > 0.0) || !std::isfinite(grid.dx) ||
      !std::isfinite(grid.dy)) {
    throw std::invalid_argument("contact grid needs nx, ny >= 1 and finite dx, dy > 0");
  }
}

namespace {
// X asinh(Y/|X|), with its limit 0 at X = 0.
double corner_term(double x, double y) { return x == 0.0 ? 0.0 : x * std::asinh(y / std::fabs(x)); }
double corner(double x, double y) { return corner_term(x, y) + corner_term(y, x); }
}  // namespace

double love_displacement(double x, double y, double a, double b, double e_star) {
  constexpr double pi = 3.14159265358979323846;
  const double sum = corner(x + a, y + b) - corner(x + a, y - b) - corner(x - a, y + b) + corner(x - a, y - b);
  return sum / (pi * e_star);
}

double love_coefficient(long ox, long oy, double dx, double dy, double e_star) {
  return love_displacement(static_cast<double>(ox) * dx, static_cast<double>(oy) * dy, 0.5 * dx, 0.5 * dy, e_star);
}

}  // namespace rollspec::contact
