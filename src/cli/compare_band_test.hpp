#pragma once
// compare's combined test over the compared bands (kernels/spectral D-26): one p-value for all
// bands at once, from the realisations' between-band covariance, and its verdict at a level.
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::cli {

struct CombinedTest {
  spectral::BandTestResult result;
  std::size_t bands = 0;
  double level = 0.05;  // the test's level alpha
  bool rejected = false;
  std::string verdict;  // one line: rejected / not rejected with p, or why there is no test
};

// The compared bands as D-26 takes them: measured band logs y (natural log of power), the model's mean
// band powers, and the between-band covariance of the band logs (p x p, row-major).
struct ChosenBands {
  std::vector<double> y, mean, cov;
};
ChosenBands chosen_bands(const io::BandLevels& b, const std::vector<std::size_t>& band,
                         const std::vector<double>& measured_db);

// `band`: indices of the compared bands in b; `measured_db`: their measured levels; records: M (0:
// not given, no test).
CombinedTest combined_test(const io::BandLevels& b, const std::vector<std::size_t>& band,
                           const std::vector<double>& measured_db, double records, double level);

}  // namespace rollspec::cli
