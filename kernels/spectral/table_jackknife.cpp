#include "kernels/spectral/table_jackknife.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

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

WidenedHalfWidth widen_half_width(double h, std::uint64_t realisations, double v, std::uint64_t surfaces,
                                  double level) {
  const double k1 = static_cast<double>(realisations) - 1.0, n1 = static_cast<double>(surfaces) - 1.0;
  if (!(h > 0.0) || !std::isfinite(h) || !(v > 0.0) || !std::isfinite(v) || !(k1 >= 1.0) || !(n1 >= 1.0))
    return {h, k1};
  const double s_w = h / t_quantile(k1, level);
  const double s2 = s_w * s_w + v;
  const double nu = s2 * s2 / (s_w * s_w * s_w * s_w / k1 + v * v / n1);
  return {t_quantile(nu, level) * std::sqrt(s2), nu};
}

}  // namespace rollspec::spectral
