#pragma once
// rollspec fit's model: the study run at a point of the parameters' box, its band levels read back,
// and ln L of the measured band levels under the prediction-interval law (kernels/spectral D-27).
// Every run keeps the study's seed, so realisation i draws the same numbers at every point (common
// random numbers) and ln L is smooth in the parameters.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "src/cli/compare_band_test.hpp"
#include "src/cli/measured_psd.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::cli {

// --vary section.key=lo:hi[:log]: the range searched, mapped onto u in [0, 1] (log: geometric).
struct VaryRange {
  std::string key;
  double lo = 0.0, hi = 1.0;
  bool log = false;
  double value(double u) const;
  double unit(double value) const;
};

// Refuses (exit 64) a malformed spec, lo >= hi, a non-finite end, or log with lo <= 0.
VaryRange parse_vary(const std::string& spec);

struct FitInputs {
  std::string study, measurement_path;
  io::SensorChoice sensor;
  std::vector<std::string> sets;  // --set passed on to every run
  std::vector<VaryRange> vary;
  Measurement measurement;
  double records = 1.0;  // M
  double fmin = 0.0, fmax = 0.0;
};

class FitModel {
 public:
  FitModel(const FitInputs& in, std::string temp_dir);
  // -ln L at u (cached: a point already run is not run again).
  double negative_log_likelihood(const std::vector<double>& u);
  // D-26's combined test of the measurement against the run at u.
  CombinedTest test_at(const std::vector<double>& u);
  int runs() const { return runs_; }
  std::size_t bands() const { return band_.size(); }
  std::uint64_t realisations() const { return realisations_; }

 private:
  io::BandLevels run_at(const std::vector<double>& u);
  void choose_bands(const io::BandLevels& b);

  const FitInputs& in_;
  std::string temp_dir_;
  std::map<std::vector<double>, double> cache_;
  std::vector<std::size_t> band_;    // indices of the compared bands in the result
  std::vector<double> measured_db_;  // their measured levels
  std::uint64_t realisations_ = 0;
  int runs_ = 0;
};

}  // namespace rollspec::cli
