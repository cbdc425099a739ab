#include "kernels/spectral/ensemble_interval.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rollspec::spectral {

namespace {

constexpr double kMaxDof = 1e12;  // beyond this the gamma-law interval is [m, m] to double precision
// Below this the gamma law is so skewed (a spread of 45 means or more) that its central quantiles
// are 0 and beyond any double, and boost's series for them do not converge: the interval is [0, inf).
constexpr double kMinDof = 1e-3;

void check(std::uint64_t realisations, double level) {
  if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("confidence level must lie in (0, 1)");
  if (realisations == 0) throw std::invalid_argument("an ensemble interval needs at least one realisation");
}

ScatterInterval none() { return {0.0, std::numeric_limits<double>::infinity(), 0.0}; }

double t_quantile(std::uint64_t realisations, double level) {
  return boost::math::quantile(boost::math::students_t(static_cast<double>(realisations - 1)),
                               1.0 - (1.0 - level) / 2.0);
}

// w = t_{K-1} / z: the log-space widening of the gamma-law interval for an estimated spread (D-21a).
double widening(std::uint64_t realisations, double level) {
  const double z = std::sqrt(2.0) * boost::math::erf_inv(level);  // z_{1-a/2}
  return t_quantile(realisations, level) / z;
}

// Satterthwaite dof of one realisation's value, 2 m^2 / s^2, or +inf for a value without scatter.
double dof_one(double mean, double std_dev) {
  if (!(std_dev > 0.0)) return std::numeric_limits<double>::infinity();
  return 2.0 * (mean / std_dev) * (mean / std_dev);
}

// The lognormal law applies when every realisation's value was positive (finite log moments).
bool lognormal_usable(const Scatter& s) { return std::isfinite(s.log_std) && s.log_mean > std::log(DBL_MIN) + 1.0; }

}  // namespace

ScatterInterval mean_interval(const Scatter& s, std::uint64_t realisations, double level) {
  check(realisations, level);
  if (realisations < kMinRealisationsForInterval) return none();
  const double K = static_cast<double>(realisations);
  const double nu = std::min(K * dof_one(s.mean, s.std_dev), kMaxDof);
  if (!(s.mean > 0.0)) return {1.0, 1.0, nu};
  ScatterInterval out{1.0, 1.0, nu};
  if (!(nu >= kMinDof)) {
    out.lower = 0.0, out.upper = std::numeric_limits<double>::infinity();
  } else if (nu < kMaxDof) {  // D-21a: gamma law, chi-square on nu dof, widened by t_{K-1}/z
    const boost::math::chi_squared chi2(nu);
    const double a = 1.0 - level, w = widening(realisations, level);
    out.lower = std::pow(nu / boost::math::quantile(chi2, 1.0 - a / 2.0), w);
    out.upper = std::pow(nu / boost::math::quantile(chi2, a / 2.0), w);
  }
  if (lognormal_usable(s) && s.log_std > 0.0) {  // D-21b: lognormal law (Cox), ln mu = ybar + s_y^2 / 2
    const double v = s.log_std * s.log_std;
    const double centre = s.log_mean + v / 2.0 - std::log(s.mean);
    const double half = t_quantile(realisations, level) * std::sqrt(v / K + v * v / (2.0 * (K - 1.0)));
    out.lower = std::min(out.lower, std::exp(centre - half));
    out.upper = std::max(out.upper, std::exp(centre + half));
  }
  return out;
}

ScatterInterval prediction_interval(const Scatter& s, std::uint64_t realisations, double records, double level) {
  check(realisations, level);
  if (!(records >= 1.0)) throw std::invalid_argument("a prediction interval needs at least one measured record");
  if (realisations < kMinRealisationsForInterval) return none();
  const double K = static_cast<double>(realisations);
  const double nu1 = std::min(dof_one(s.mean, s.std_dev), kMaxDof / std::max(K, records));
  ScatterInterval out{1.0, 1.0, K * nu1};
  if (!(s.mean > 0.0)) return out;
  if (!(std::min(records, K) * nu1 >= kMinDof)) {
    out.lower = 0.0, out.upper = std::numeric_limits<double>::infinity();
  } else if (K * nu1 < kMaxDof) {  // D-22a: m_M / m_K ~ F(M nu_1, K nu_1), widened by t_{K-1}/z
    const boost::math::fisher_f f(records * nu1, K * nu1);
    const double a = 1.0 - level, w = widening(realisations, level);
    out.lower = std::pow(boost::math::quantile(f, a / 2.0), w);
    out.upper = std::pow(boost::math::quantile(f, 1.0 - a / 2.0), w);
  }
  if (lognormal_usable(s) && s.log_std > 0.0) {
    // D-22b: both means taken lognormal with their moments (Fenton-Wilkinson), CV^2 = e^{s_y^2} - 1.
    const double cv2 = std::expm1(s.log_std * s.log_std);
    const double vm = std::log1p(cv2 / records), vk = std::log1p(cv2 / K);
    const double half = t_quantile(realisations, level) * std::sqrt(vm + vk), centre = (vk - vm) / 2.0;
    out.lower = std::min(out.lower, std::exp(centre - half));
    out.upper = std::max(out.upper, std::exp(centre + half));
  }
  return out;
}

}  // namespace rollspec::spectral
