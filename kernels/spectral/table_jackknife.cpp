#include "kernels/spectral/table_jackknife.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <algorithm>
#include <limits>
#include <vector>

namespace rollspec::spectral {

namespace {
double t_quantile(double dof, double level) {
  return boost::math::quantile(boost::math::students_t(dof), 1.0 - (1.0 - level) / 2.0);
}
}  // namespace

double jackknife_variance(const double* theta, std::size_t n) {
  if (n < 2) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(theta[i])) return std::numeric_limits<double>::quiet_NaN();
    sum += theta[i];
  }
  const double mean = sum / static_cast<double>(n);
  double sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) sq += (theta[i] - mean) * (theta[i] - mean);
  return static_cast<double>(n - 1) / static_cast<double>(n) * sq;
}

double jackknife_variance_reference(const double* theta, std::size_t n) {
  if (n < 2) return 0.0;
  double pairs = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) pairs += (theta[i] - theta[j]) * (theta[i] - theta[j]);
  const double N = static_cast<double>(n);
  return (N - 1.0) / N * pairs / N;
}

namespace {
// (10/ln 10)^2 (N - 1)/N sum_i s_i^2 / (K mean^2): the noise of (a) in dB^2 (c).
double noise_db2(double sum_s2, double mean, std::size_t n, std::uint64_t K) {
  const double N = static_cast<double>(n), c = 10.0 / std::log(10.0);
  return c * c * (N - 1.0) / N * sum_s2 / (static_cast<double>(K) * mean * mean);
}
}  // namespace

double paired_noise_variance(double q, const double* m, std::size_t n, std::uint64_t K) {
  if (n < 2 || K < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += m[i];
  mean /= static_cast<double>(n);
  if (!(mean > 0.0) || !std::isfinite(q)) return std::numeric_limits<double>::quiet_NaN();
  double between = 0.0;
  for (std::size_t i = 0; i < n; ++i) between += (m[i] - mean) * (m[i] - mean);
  const double k = static_cast<double>(K);
  return noise_db2(std::max(0.0, q - k * between) / (k - 1.0), mean, n, K);
}

double paired_noise_variance_reference(const double* x, std::size_t n, std::uint64_t K) {
  if (n < 2 || K < 2) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> d(n * K);
  double mean = 0.0;
  for (std::uint64_t r = 0; r < K; ++r) {
    double xr = 0.0;
    for (std::size_t i = 0; i < n; ++i) xr += x[i * K + r];
    xr /= static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) d[i * K + r] = x[i * K + r] - xr;
    mean += xr;
  }
  mean /= static_cast<double>(K);
  double sum_s2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double di = 0.0, ss = 0.0;
    for (std::uint64_t r = 0; r < K; ++r) di += d[i * K + r];
    di /= static_cast<double>(K);
    for (std::uint64_t r = 0; r < K; ++r) ss += (d[i * K + r] - di) * (d[i * K + r] - di);
    sum_s2 += ss / static_cast<double>(K - 1);
  }
  if (!(mean > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return noise_db2(sum_s2, mean, n, K);
}

WidenedHalfWidth widen_half_width(double h, std::uint64_t realisations, double v, double table_dof, double level) {
  const double k1 = static_cast<double>(realisations) - 1.0, n1 = table_dof;
  if (!(h > 0.0) || !std::isfinite(h) || !(v > 0.0) || !std::isfinite(v) || !(k1 >= 1.0) || !(n1 >= 1.0))
    return {h, k1};
  const double s_w = h / t_quantile(k1, level);
  const double s2 = s_w * s_w + v;
  const double nu = s2 * s2 / (s_w * s_w * s_w * s_w / k1 + v * v / n1);
  return {t_quantile(nu, level) * std::sqrt(s2), nu};
}

}  // namespace rollspec::spectral
