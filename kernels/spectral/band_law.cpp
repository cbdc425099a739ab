#include "kernels/spectral/band_law.hpp"

#include <boost/math/special_functions/polygamma.hpp>
#include <boost/math/tools/roots.hpp>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace rollspec::spectral {

namespace {
constexpr double kLognormalSkew = 1e-3;  // below: the lognormal limit (the correction is below 1e-3 s^{3/2})
constexpr double kMaxSkew = 1.99;        // ln of a gamma law: skewness in (-2, 0)
}  // namespace

double log_gamma_skewness(double k) {
  const double t = boost::math::trigamma(k);
  return boost::math::polygamma(2, k) / (t * std::sqrt(t));
}

double band_cv2(double s, double g1) {
  if (!(s >= 0.0) || !std::isfinite(s) || !std::isfinite(g1))
    throw std::invalid_argument("band law: the log variance must be finite and >= 0, the log skewness finite");
  const double lognormal = std::expm1(s);
  const double skew = std::fmin(std::fabs(g1), kMaxSkew);
  if (s == 0.0 || skew < kLognormalSkew) return lognormal;
  // D-26d: the shape k = 1/Q^2 whose ln gamma has skewness -|g1| (monotone in k), solved in ln k.
  std::uintmax_t iterations = 200;
  const auto f = [&](double lnk) { return -log_gamma_skewness(std::exp(lnk)) - skew; };
  const auto root =
      boost::math::tools::toms748_solve(f, std::log(1e-6), std::log(1e7), f(std::log(1e-6)), f(std::log(1e7)),
                                        boost::math::tools::eps_tolerance<double>(48), iterations);
  const double k = std::exp(0.5 * (root.first + root.second));
  // sigma from var ln x = sigma^2 psi'(k) / Q^2; a = sigma / Q (Q > 0 for a left-skewed ln x), so x ~ G^a and
  // E x^r / (E x)^r = Gamma(k + r a) Gamma(k)^{r-1} / Gamma(k + a)^r.
  const double a = std::copysign(std::sqrt(s / boost::math::trigamma(k)), -g1);
  if (!(k + 2.0 * a > 0.0)) return lognormal;  // no finite variance: the lognormal reading
  // The lgamma sum loses about eps k ln k; where that is above 1e-6 of s (tiny spreads), the cumulant form
  // ln(1 + c^2) = K(2) - 2 K(1) = s + g1 s^{3/2} + O(s^2) is the more accurate.
  if (k * std::log(k + 2.0) * DBL_EPSILON > 1e-6 * s) return std::expm1(s + std::copysign(skew, g1) * s * std::sqrt(s));
  return std::expm1(std::lgamma(k + 2.0 * a) + std::lgamma(k) - 2.0 * std::lgamma(k + a));
}

}  // namespace rollspec::spectral
