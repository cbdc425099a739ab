#include "kernels/spectral/covariance_shrinkage.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollspec::spectral {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The bands that vary over the units, standardised (D-31e b's x): n x q.
RowMatrix standardised(const double* x, std::size_t n, std::size_t p) {
  const Eigen::Map<const RowMatrix> a(x, static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(p));
  if (!a.allFinite()) throw std::invalid_argument("covariance shrinkage: a unit's value is not finite");
  std::vector<Eigen::Index> keep;
  RowMatrix z(a.rows(), a.cols());
  for (Eigen::Index k = 0; k < a.cols(); ++k) {
    const Eigen::VectorXd c = a.col(k).array() - a.col(k).mean();
    const double sd = std::sqrt(c.squaredNorm() / static_cast<double>(n - 1));
    if (!(sd > 1e-12 * std::max(1.0, a.col(k).cwiseAbs().maxCoeff()))) continue;  // a constant band
    z.col(static_cast<Eigen::Index>(keep.size())) = c / sd;
    keep.push_back(k);
  }
  return z.leftCols(static_cast<Eigen::Index>(keep.size()));
}

}  // namespace

double shrinkage_intensity(const double* x, std::size_t n, std::size_t p) {
  if (n < 3 || p < 2) return 1.0;
  const RowMatrix z = standardised(x, n, p);
  if (z.cols() < 2) return 1.0;
  const double nn = static_cast<double>(n);
  // sum_i w_ikl = (Z^T Z)_kl and sum_i w_ikl^2 = ((Z.Z)^T (Z.Z))_kl, so sum_i (w - mean w)^2 = the second
  // minus the first squared over n.
  const RowMatrix s1 = z.transpose() * z;
  const RowMatrix z2 = z.array().square();
  const RowMatrix s2 = z2.transpose() * z2;
  const RowMatrix r = s1 / (nn - 1.0);
  const RowMatrix var_r = nn / std::pow(nn - 1.0, 3) * (s2.array() - s1.array().square() / nn).matrix();
  const double off_var = var_r.sum() - var_r.trace(), off_r2 = r.squaredNorm() - r.diagonal().squaredNorm();
  if (!(off_r2 > 0.0)) return 1.0;
  return std::clamp(off_var / off_r2, 0.0, 1.0);
}

double shrinkage_intensity_reference(const double* x, std::size_t n, std::size_t p) {
  if (n < 3 || p < 2) return 1.0;
  std::vector<std::vector<double>> z;  // the standardised bands that vary
  for (std::size_t k = 0; k < p; ++k) {
    double mean = 0.0, ss = 0.0, top = 1.0;
    for (std::size_t i = 0; i < n; ++i) mean += x[i * p + k] / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(x[i * p + k])) throw std::invalid_argument("covariance shrinkage: a value is not finite");
      ss += (x[i * p + k] - mean) * (x[i * p + k] - mean);
      top = std::max(top, std::fabs(x[i * p + k]));
    }
    const double sd = std::sqrt(ss / static_cast<double>(n - 1));
    if (!(sd > 1e-12 * top)) continue;
    std::vector<double> col(n);
    for (std::size_t i = 0; i < n; ++i) col[i] = (x[i * p + k] - mean) / sd;
    z.push_back(col);
  }
  const double nn = static_cast<double>(n);
  double off_var = 0.0, off_r2 = 0.0;
  for (std::size_t k = 0; k < z.size(); ++k)
    for (std::size_t l = 0; l < z.size(); ++l) {
      if (k == l) continue;
      double wbar = 0.0;
      for (std::size_t i = 0; i < n; ++i) wbar += z[k][i] * z[l][i] / nn;
      double dev = 0.0;
      for (std::size_t i = 0; i < n; ++i) dev += (z[k][i] * z[l][i] - wbar) * (z[k][i] * z[l][i] - wbar);
      const double r = nn / (nn - 1.0) * wbar;
      off_var += nn / ((nn - 1.0) * (nn - 1.0) * (nn - 1.0)) * dev;
      off_r2 += r * r;
    }
  if (!(off_r2 > 0.0)) return 1.0;
  return std::min(1.0, std::max(0.0, off_var / off_r2));
}

void shrink_toward_diagonal(double* covariance, std::size_t p, double lambda) {
  for (std::size_t k = 0; k < p; ++k)
    for (std::size_t l = 0; l < p; ++l)
      if (k != l) covariance[k * p + l] *= 1.0 - lambda;
}

}  // namespace rollspec::spectral
