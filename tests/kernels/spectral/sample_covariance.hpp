#pragma once
// Test support: an ensemble's sample covariance S with its own Wishart scatter, drawn as the Monte-Carlo
// tests of the band test (D-26, D-31) draw it: K - 1 columns L e, e standard normal from z in column order.
#include <Eigen/Dense>

namespace rollspec::spectral::testing {

template <class Normal>
Eigen::MatrixXd sample_covariance(const Eigen::MatrixXd& l, Eigen::Index draws, Normal&& z) {
  Eigen::MatrixXd x(l.rows(), draws);
  for (Eigen::Index c = 0; c < draws; ++c) {
    Eigen::VectorXd e(l.rows());
    for (Eigen::Index b = 0; b < l.rows(); ++b) e(b) = z();
    x.col(c) = l * e;
  }
  return x * x.transpose() / double(draws);
}

}  // namespace rollspec::spectral::testing
