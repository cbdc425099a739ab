#pragma once
// compare's combined test over the compared bands (kernels/spectral D-26): one p-value for all
// bands at once, from the realisations' between-band covariance, and its verdict at a level.
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::compare {

struct CombinedTest {
  spectral::BandTestResult result;
  std::size_t bands = 0;
  double level = 0.05;  // the test's level alpha
  bool rejected = false;
  std::string verdict;  // one line: rejected / not rejected with p, or why there is no test
};

// The compared bands as D-26 takes them: measured band logs y (natural log of power), the model's mean
// band powers, the between-band covariance of the band logs (p x p, row-major), and each band's squared
// coefficient of variation of one realisation's band power, read from its log variance and log skewness through
// the generalised gamma law (D-26d; empty: the result has no /bands/log_skewness, and V reads it as e^{S_bb} - 1,
// D-26a).
struct ChosenBands {
  std::vector<double> y, mean, cov, cv2;
  const double* cv2_or_null() const { return cv2.empty() ? nullptr : cv2.data(); }
};
ChosenBands chosen_bands(const io::BandLevels& b, const std::vector<std::size_t>& band,
                         const std::vector<double>& measured_db);

// How many of the table's terms a verdict carries (kernels/spectral D-31): 2 for a rig with another
// surface of this roughness (the model's table and the rig's surface each deviate from the roughness's
// mean), 0 for the very surface the table was built on (--same-surface).
constexpr double kNewSurfaceTableFactor = 2.0;

// D-31d: a spectral table's band variances (independent bands) are pooled over each band and its neighbour
// on either side among the compared bands, in the test and the prediction intervals alike.
constexpr std::size_t kSpectralTableSmoothing = 1;

// Draws of D-31's parametric bootstrap: the p-value's own standard error is below 0.0022 at p = 0.05.
constexpr std::size_t kBootstrapDraws = 10000;

// `band`: indices of the compared bands in b; `measured_db`: their measured levels; records: M (0:
// not given, no test); table_factor: c of D-31 (0: none; the F law of D-26); noise: the logger noise's terms of
// the compared bands (D-33c; null: none).
CombinedTest combined_test(const io::BandLevels& b, const std::vector<std::size_t>& band,
                           const std::vector<double>& measured_db, double records, double level,
                           double table_factor = 0.0, const spectral::BandNoise* noise = nullptr);

// The table term's variance of band k of b in dB^2 (D-30a times the variance factor; 0 without a term).
double table_band_variance_db(const io::BandLevels& b, std::size_t k);

}  // namespace rollspec::compare
