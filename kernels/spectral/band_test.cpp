#include "kernels/spectral/band_test.hpp"

#include "kernels/spectral/gauss_jordan.hpp"

#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollspec::spectral {

double log_mean_variance(double s, double n) { return std::log1p(std::expm1(s) / n); }

// D-26d: Fenton-Wilkinson on the mean's own linear moments, E = mu, var = sigma^2 / n.
double log_mean_variance_cv2(double cv2, double n) { return std::log1p(cv2 / n); }

BandTerms band_terms(double s, double K, double M, double h, const BandNoise* noise, const double* cv2) {
  if (cv2 && !(*cv2 >= 0.0 && std::isfinite(*cv2)))
    throw std::invalid_argument("band test: a band's coefficient of variation is negative or not finite");
  const double c2 = cv2 ? *cv2 : std::expm1(s);  // D-26d; D-26a's lognormal reading without it
  const double vm = log_mean_variance_cv2(c2, M), vk = log_mean_variance_cv2(c2, K);
  BandTerms t;
  if (!noise) {
    t.g = s > 0.0 ? std::sqrt((vm + h * vk) / s) : std::sqrt(1.0 / M + h / K);  // the limit s -> 0
    t.offset = 0.5 * (vk - vm);
    return t;
  }
  // D-33c c: the signal's part of ln(m + N) scaled by a^2, the noise's terms beside it.
  const double a2 = noise->signal_share;
  t.g = s > 0.0 ? std::sqrt(a2 * (vm + h * vk) / s) : std::sqrt(a2 * (1.0 / M + h / K));
  t.offset = noise->shift + 0.5 * ((a2 * vk + noise->estimate) - (a2 * vm + noise->measured));
  t.diagonal = noise->measured + noise->estimate;
  return t;
}

namespace {

// D-26a, b with the model mean's variance scaled by h (D-27i): g_b^2 = (V_M,bb + h V_K,bb) / S_bb; with the
// logger noise of D-33c where given.
void deviation(const double* y, const double* mean, const double* cov, std::size_t p, double K, double M, double h,
               const BandNoise* noise, const double* cv2, std::vector<double>& d, std::vector<double>& v) {
  if (!(M >= 1.0) || !(K >= 2.0)) throw std::invalid_argument("band test: needs records >= 1 and K >= 2");
  if (!(h >= 0.0)) throw std::invalid_argument("band likelihood: the mean's variance share must be >= 0");
  d.assign(p, 0.0);
  v.assign(p * p, 0.0);
  std::vector<double> g(p), diagonal(p);
  for (std::size_t b = 0; b < p; ++b) {
    if (!(mean[b] > 0.0) || !std::isfinite(y[b])) throw std::invalid_argument("band test: a band without power");
    const BandTerms t = band_terms(cov[b * p + b], K, M, h, noise ? noise + b : nullptr, cv2 ? cv2 + b : nullptr);
    g[b] = t.g;
    diagonal[b] = t.diagonal;
    d[b] = y[b] - (std::log(mean[b]) + t.offset);
  }
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c) v[b * p + c] = g[b] * cov[b * p + c] * g[c];
  if (noise)
    for (std::size_t b = 0; b < p; ++b) {
      v[b * p + b] += diagonal[b];
      if (noise[b].cross)  // D-33e: the noise's covariance between bands that share bins
        for (std::size_t c = 0; c < p; ++c)
          if (c != b) v[b * p + c] += noise[b].cross[c];
    }
}

}  // namespace

// Each band's variance from Fenton-Wilkinson (on its CV^2 where given, D-26d), the correlations those of S:
// V stays S scaled band by band, so T^2 keeps Hotelling's law; the elementwise ln(1 + (e^S - 1)/n) of a noisy S
// does not (D-26a).
void band_deviation(const double* y, const double* mean, const double* cov, std::size_t p, double K, double M,
                    std::vector<double>& d, std::vector<double>& v, const BandNoise* noise, const double* cv2) {
  deviation(y, mean, cov, p, K, M, 1.0, noise, cv2, d, v);
}

double whitened_square(std::vector<double>& d, std::vector<double>& v, std::size_t p, double* log_det) {
  for (std::size_t j = 0; j < p; ++j) {
    for (std::size_t i = j; i < p; ++i) {
      double s = v[i * p + j];
      for (std::size_t k = 0; k < j; ++k) s -= v[i * p + k] * v[j * p + k];
      if (i == j) {
        if (!(s > 0.0)) throw std::invalid_argument("band test: the band covariance is not positive definite");
        v[j * p + j] = std::sqrt(s);
      } else
        v[i * p + j] = s / v[j * p + j];
    }
  }
  double t2 = 0.0, ld = 0.0;
  for (std::size_t i = 0; i < p; ++i) {
    double s = d[i];
    for (std::size_t k = 0; k < i; ++k) s -= v[i * p + k] * d[k];
    d[i] = s / v[i * p + i];
    t2 += d[i] * d[i];
    ld += 2.0 * std::log(v[i * p + i]);
  }
  if (log_det) *log_det = ld;
  return t2;
}

BandTestResult band_test(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                         std::uint64_t realisations, double records, const BandNoise* noise, const double* cv2) {
  BandTestResult r;
  r.needed = p + kExtraRealisations;
  if (p == 0 || realisations < r.needed) return r;
  std::vector<double> d, v;
  band_deviation(measured_log, mean, covariance, p, static_cast<double>(realisations), records, d, v, noise, cv2);
  hotelling_f_law(r, whitened_square(d, v, p, nullptr), static_cast<double>(realisations - 1), static_cast<double>(p));
  return r;
}

void hotelling_f_law(BandTestResult& r, double t2, double nu, double p) {
  r.defined = true;
  r.t2 = t2;
  r.dof1 = p;
  r.dof2 = nu - p + 1.0;
  r.f = r.dof2 / (nu * p) * t2;
  r.p_value = boost::math::cdf(boost::math::complement(boost::math::fisher_f(r.dof1, r.dof2), r.f));
}

double likelihood_temper(double n, std::size_t p) {
  // The covariance is estimated with n dof: its inverse overstates the precision by n / (n - p - 1) and
  // the weights' noise adds (n - 1) / (n - p) to the estimate's variance (D-27b). ln L is tempered by the
  // inverse of both: the maximum stays the Gaussian one, the profile intervals widen to keep their level.
  const double pp = static_cast<double>(p);
  if (!(n - pp - 1.0 > 0.0)) throw std::invalid_argument("band likelihood: needs K > p + 2 realisations");
  return (n - pp) * (n - pp - 1.0) / (n * (n - 1.0));
}

double band_log_likelihood(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                           std::uint64_t realisations, double records) {
  return band_log_likelihood(measured_log, mean, covariance, p, realisations, records, LikelihoodTerms{});
}

double band_log_likelihood(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                           std::uint64_t realisations, double records, const LikelihoodTerms& terms) {
  std::vector<double> d, v;
  deviation(measured_log, mean, covariance, p, static_cast<double>(realisations), records, terms.mean_share, nullptr,
            nullptr, d, v);
  if (terms.table)
    for (std::size_t i = 0; i < p * p; ++i) v[i] += terms.table[i];
  double log_det = 0.0;
  const double t2 = whitened_square(d, v, p, &log_det);
  const double n = terms.covariance_dof > 0.0 ? terms.covariance_dof : static_cast<double>(realisations) - 1.0;
  return -0.5 * likelihood_temper(n, p) * (t2 + log_det);
}

double band_test_t2_reference(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                              std::uint64_t realisations, double records, const double* cv2) {
  // V and d written out plainly from D-26a, b, d (not through band_deviation).
  const double K = static_cast<double>(realisations), M = records;
  std::vector<double> d(p), v(p * p), vb(p);
  for (std::size_t b = 0; b < p; ++b) {
    const double s = covariance[b * p + b], c2 = cv2 ? cv2[b] : std::exp(s) - 1.0;
    const double vm = std::log(1.0 + c2 / M), vk = std::log(1.0 + c2 / K);
    vb[b] = vm + vk;
    d[b] = measured_log[b] - std::log(mean[b]) - 0.5 * (vk - vm);
  }
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c)
      v[b * p + c] = covariance[b * p + c] * std::sqrt(vb[b] * vb[c] / (covariance[b * p + b] * covariance[c * p + c]));
  std::vector<double> inv;
  if (!gauss_jordan_inverse(v, p, inv)) return NAN;  // a singular V has no T^2
  double t2 = 0.0;
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j) t2 += d[i] * inv[i * p + j] * d[j];
  return t2;
}

}  // namespace rollspec::spectral
