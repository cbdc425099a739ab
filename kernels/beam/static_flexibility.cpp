#include "kernels/beam/static_flexibility.hpp"

#include <stdexcept>

namespace rollspec::beam {

double static_flexibility(Support support, double length, double bending_stiffness, double x, double a) {
  const double l = length;
  if (!(l > 0.0) || !(bending_stiffness > 0.0)) throw std::invalid_argument("static_flexibility: L and EI must be > 0");
  if (!(x >= 0.0 && x <= l && a >= 0.0 && a <= l))
    throw std::invalid_argument("static_flexibility: x, a outside [0, L]");
  if (x > a) {  // mirror (B7)
    x = l - x;
    a = l - a;
  }
  const double b = l - a;
  if (support == Support::clamped_clamped)
    return b * b * x * x * (3.0 * a * l - 3.0 * a * x - b * x) / (6.0 * bending_stiffness * l * l * l);
  return b * x * (l * l - b * b - x * x) / (6.0 * bending_stiffness * l);
}

}  // namespace rollspec::beam
