#include "kernels/beam/quadratic_hold_step.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace rollspec::beam {

QuadraticHoldStep QuadraticHoldStep::make(double omega, double zeta, double h) {
  if (!(omega >= 0.0) || !(zeta >= 0.0) || !(h > 0.0) || !std::isfinite(omega * zeta * h))
    throw std::invalid_argument("QuadraticHoldStep: needs omega >= 0, zeta >= 0, h > 0, all finite");
  Eigen::Matrix<double, 5, 5> m = Eigen::Matrix<double, 5, 5>::Zero();
  m(0, 1) = 1.0;
  m(1, 0) = -omega * omega;
  m(1, 1) = -2.0 * zeta * omega;
  m(1, 2) = 1.0;
  m(2, 3) = 1.0;
  m(3, 4) = 1.0;
  const Eigen::Matrix<double, 5, 5> e = (m * h).exp();
  QuadraticHoldStep s{};
  s.a00 = e(0, 0);
  s.a01 = e(0, 1);
  s.a10 = e(1, 0);
  s.a11 = e(1, 1);
  const double h2 = h * h;
  // (B36): split f(0), f'(0), f''(0) into the three step values.
  s.bm = -e(0, 3) / (2.0 * h) + e(0, 4) / h2;
  s.b0 = e(0, 2) - 2.0 * e(0, 4) / h2;
  s.b1 = e(0, 3) / (2.0 * h) + e(0, 4) / h2;
  s.cm = -e(1, 3) / (2.0 * h) + e(1, 4) / h2;
  s.c0 = e(1, 2) - 2.0 * e(1, 4) / h2;
  s.c1 = e(1, 3) / (2.0 * h) + e(1, 4) / h2;
  return s;
}

}  // namespace rollspec::beam
