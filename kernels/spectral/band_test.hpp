#pragma once
// Combined test of a measurement's band levels against an ensemble (theory D-26): a Hotelling-type
// T^2 of the measured-minus-predicted band logs with the covariance of an M-record measurement plus
// that of the K-realisation mean, both the realisations' between-band covariance of ln x scaled band by
// band to each band's Fenton-Wilkinson variance,
// referred to F(p, K - p) (K - 1 dof of the covariance estimate).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/spectral/band_noise.hpp"

namespace rollspec::spectral {

struct BandTestResult {
  bool defined = false;           // false: too few realisations for p bands (needed says how many)
  double t2 = 0.0;                // Hotelling T^2
  double f = 0.0;                 // (nu - p + 1) / (nu p) T^2, nu = K - 1
  double dof1 = 0.0, dof2 = 0.0;  // F(p, K - p)
  double p_value = 1.0;           // P(F(p, K - p) >= f)
  std::uint64_t needed = 0;       // realisations the test needs for p bands: p + kExtraRealisations
  std::size_t draws = 0;          // 0: p from the F law; else from a parametric bootstrap of B draws (D-31)
};

// Fenton-Wilkinson: variance of ln of an n-record mean, ln(1 + (e^s - 1) / n), from the variance s of
// one record's ln band average (D-26a: one record's CV^2 read as e^s - 1, right for a lognormal law only).
// fit's likelihood (D-27) still takes a band's V_bb as log_mean_variance(s, M) + log_mean_variance(s, K).
double log_mean_variance(double s, double n);

// D-26d: the same variance from one record's squared coefficient of variation cv2 = var x / (E x)^2 of the band
// power itself: ln(1 + cv2 / n). compare's test takes it with cv2 from band_law.hpp's band_cv2.
double log_mean_variance_cv2(double cv2, double n);

// One band's terms of D-26a, b: g_b of V = G S G, the offset o_b of d_b = y_b - (ln m_b + o_b), and the variance
// the logger noise adds to V's diagonal. s = S_bb, K, M, h the model mean's variance share (D-27i; 1: one run).
// Without noise (null): g_b^2 = (V_M,bb + h V_K,bb) / S_bb, o_b = (V_K,bb - V_M,bb) / 2, nothing added. With
// noise (D-33c c): the signal's terms times a^2, o_b = ln(1 + N/m) + (a^2 V_K + D_P - a^2 V_M - D_M) / 2, and
// D_M + D_P on the diagonal (BandNoise's measured and estimate). cv2: the band's CV^2 of one realisation's band
// power (D-26d: V_n,bb = ln(1 + cv2 / n)); null: read from s as e^s - 1 (D-26a's lognormal reading).
struct BandTerms {
  double g = 0.0, offset = 0.0, diagonal = 0.0;
};
BandTerms band_terms(double s, double realisations, double records, double h, const BandNoise* noise,
                     const double* cv2 = nullptr);

// D-26a, b: d = y - (ln m + (V_K,bb - V_M,bb) / 2) and V = G S G (p x p, row-major), G_bb^2 =
// (V_M,bb + V_K,bb) / S_bb, for measured band logs y, the model's mean band powers m, their log covariance S,
// K realisations and M records; with `noise` (p bands, D-33c) each band's terms as band_terms gives them; with
// `cv2` (p bands) each band's V_n,bb from its CV^2 (D-26d), else from e^{S_bb} - 1 (D-26a).
// Throws std::invalid_argument on a band without power or M < 1, K < 2, or a cv2 negative or not finite.
void band_deviation(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                    double realisations, double records, std::vector<double>& d, std::vector<double>& v,
                    const BandNoise* noise = nullptr, const double* cv2 = nullptr);

// Cholesky V = L L^T in place (lower triangle) and |L^{-1} d|^2 (d is overwritten); ln det V into
// log_det when given. Throws std::invalid_argument when V is not positive definite.
double whitened_square(std::vector<double>& d, std::vector<double>& v, std::size_t p, double* log_det);

// Realisations beyond p that the test asks for (F denominator dof >= this + 1).
constexpr std::uint64_t kExtraRealisations = 4;

// measured_log[b]: ln of the measured band average; mean[b]: ensemble mean of the realisations'
// band averages (not its log); covariance: p x p row-major, between-band covariance (K - 1) of the
// realisations' ln band averages; records: M >= 1; realisations: K. Throws std::invalid_argument on
// a covariance that is not positive definite or non-positive inputs.
// D-26's F law of T^2 with nu = K - 1 and p compared dimensions: fills r's statistic, dofs, F and p-value.
void hotelling_f_law(BandTestResult& r, double t2, double nu, double p);

// `noise`: D-33c's terms of the p bands (null: none); the F law is kept (the noise terms are known far better than
// S, so T^2's tail lies between chi^2_p and Hotelling's: the test is at most slightly conservative). `cv2`: the p
// bands' CV^2 of one realisation's band power (D-26d; null: e^{S_bb} - 1, D-26a).
BandTestResult band_test(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                         std::uint64_t realisations, double records, const BandNoise* noise = nullptr,
                         const double* cv2 = nullptr);

// ln L of the measured band logs under the same Gaussian law (theory D-27): -c (T^2 + ln det V) / 2,
// without the constant -p ln(2 pi) / 2; c = (n - p)(n - p - 1) / (n (n - 1)), n = K - 1, corrects for
// the covariance estimated from K realisations (D-27b). Throws as band_test does, and for K <= p + 2.
double band_log_likelihood(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                           std::uint64_t realisations, double records);

// The terms a fit's likelihood adds to D-27a. mean_share h: the model mean's own variance is h V_K
// (1: one run's K-realisation mean; a response surface's leverage h(u), D-27i), the offset of d keeps
// the whole V_K (each run's log of a mean is biased by it). covariance_dof: the degrees of freedom of
// S in c (0: K - 1 of one run; S pooled over runs has more, D-27i). table: c_T Sigma_T (p x p,
// natural log squared, already times its factor; null: none) added to V (D-31a).
struct LikelihoodTerms {
  double mean_share = 1.0;
  double covariance_dof = 0.0;
  const double* table = nullptr;
};

// ln L of D-27a with those terms; with the defaults it is band_log_likelihood above, bit for bit.
double band_log_likelihood(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                           std::uint64_t realisations, double records, const LikelihoodTerms& terms);

// D-27b's c for S of n degrees of freedom and p bands: (n - p)(n - p - 1) / (n (n - 1)); throws
// std::invalid_argument for n <= p + 1.
double likelihood_temper(double n, std::size_t p);

// The same T^2 with d and V written out plainly and a Gauss-Jordan inverse, for tests (cv2 as band_test's).
double band_test_t2_reference(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                              std::uint64_t realisations, double records, const double* cv2 = nullptr);

}  // namespace rollspec::spectral
