#include "kernels/spectral/tail_check.hpp"

#include <algorithm>
#include <cmath>

namespace rollspec::spectral {

namespace {

constexpr double kCochran = 25.0;  // K > 25 G1^2 (Cochran 1977, sect. 2.15)
// Standard errors of a normal sample's G1 taken off before the rule: the worst of up to ~100
// row-bands of a Gaussian scene then rarely asks for more (D-29).
constexpr double kStandardErrors = 2.0;

// G1 from the central moments m2, m3 (divisor K) and the rule's K (D-29a-c).
TailCheck from_moments(std::uint64_t realisations, double m2, double m3) {
  TailCheck out;
  const double K = static_cast<double>(realisations);
  if (realisations < 3 || !(m2 > 0.0) || !std::isfinite(m3)) return out;
  out.defined = true;
  out.skewness = m3 / std::pow(m2, 1.5) * std::sqrt(K * (K - 1.0)) / (K - 2.0);
  out.standard_error = std::sqrt(6.0 * K * (K - 1.0) / ((K - 2.0) * (K + 1.0) * (K + 3.0)));
  const double excess = std::max(0.0, out.skewness - kStandardErrors * out.standard_error);
  out.needed = static_cast<std::uint64_t>(std::ceil(kCochran * excess * excess));
  return out;
}

}  // namespace

TailCheck tail_check(std::uint64_t realisations, double sum, double sum_sq, double sum_cubes) {
  if (realisations < 3) return {};
  const double K = static_cast<double>(realisations), m = sum / K;
  // Central sums from raw ones: sum (y - m)^2 = S2 - K m^2, sum (y - m)^3 = S3 - 3 m S2 + 2 K m^3.
  const double c2 = std::max(0.0, sum_sq - K * m * m), c3 = sum_cubes - 3.0 * m * sum_sq + 2.0 * K * m * m * m;
  // Below a relative 1e-12 of the raw sums the scatter is rounding, not spread.
  if (!(c2 > 1e-12 * sum_sq)) return {};
  return from_moments(realisations, c2 / K, c3 / K);
}

TailCheck tail_check_reference(const double* y, std::uint64_t realisations) {
  if (realisations < 3) return {};
  double m = 0.0;
  for (std::uint64_t i = 0; i < realisations; ++i) m += y[i];
  m /= static_cast<double>(realisations);
  double m2 = 0.0, m3 = 0.0;
  for (std::uint64_t i = 0; i < realisations; ++i) {
    const double d = y[i] - m;
    m2 += d * d;
    m3 += d * d * d;
  }
  return from_moments(realisations, m2 / static_cast<double>(realisations), m3 / static_cast<double>(realisations));
}

}  // namespace rollspec::spectral
