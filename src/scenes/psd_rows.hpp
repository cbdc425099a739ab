#pragma once
// One realisation's result vector for a scene that writes /psd and /bands:
//   [PSD rows: rows x nf][band values: rows x nb][ln of both: rows x (nf + nb)][the scene's extras]
//   [products of a row's band logs: rows x nb (nb + 1) / 2, pairs b <= c][cubes of the band logs: rows x nb]
// Rows are the sensors, then their mean when the study asks for it. A row's band values are its
// third-octave band averages (D-17); their scatter over realisations gives the band intervals
// (D-21), which the band average of the mean PSD alone cannot. The logarithms give the moments of
// ln x that the lognormal law of D-21b needs (the driver sums values and their squares). The
// products give the between-band covariance of the band logs that compare's combined test needs
// (D-26); they sit after the extras so that every earlier value keeps its place and its sums. The
// cubes give the skewness of the band logs, whether K suffices for the band intervals (D-29).
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/io/psd_result.hpp"
#include "src/scenes/result_shape.hpp"

namespace rollspec::scenes {

class PsdRows {
 public:
  // `sensor_mean` adds a row "sensor_mean" when there is more than one sensor.
  PsdRows(std::vector<std::string> sensors, bool sensor_mean, std::vector<double> frequency, double band_min,
          double band_max, std::size_t extras);

  std::size_t rows() const { return names_.size(); }
  std::size_t sensors() const { return sensors_; }
  std::size_t n_freq() const { return frequency_.size(); }
  std::size_t size() const { return 2 * spectra() + extras_ + products() + rows() * bands_.size(); }

  // The leading values in linear units, what the table jackknife pairs (D-30c): rows x nf PSD, then
  // rows x nb band values.
  std::size_t linear_values() const { return spectra(); }

  double* row(double* values, std::size_t r) const { return values + r * n_freq(); }
  std::size_t extra_index(std::size_t i) const { return 2 * spectra() + i; }
  double* extras(double* values) const { return values + extra_index(0); }

  // After the sensor rows are written: fills the sensor-mean row, every row's band values and the
  // logarithms of all of them.
  void finish(double* values) const;

  // The ensemble of the rows (means, scatter of bins and bands, the bands' tail check) for
  // io::write_psd_result; the caller sets units, quantity and confidence.
  io::PsdEnsemble ensemble(const ensemble::EnsembleSums& sums) const;
  // ensemble() with the Welch estimator's record: its configuration, window bandwidth, the record of
  // `record_samples` each realisation's rows were estimated from (its stationary D-16 dof times K, for
  // information) and the intervals' confidence.
  io::PsdEnsemble welch_ensemble(const ensemble::EnsembleSums& sums, const spectral::WelchPlan& welch,
                                 std::size_t record_samples, double confidence) const;

  // The rows, bins and bands /psd and /bands are written with.
  ResultShape shape() const;

 private:
  std::size_t spectra() const { return rows() * (n_freq() + bands_.size()); }  // PSD and band values
  std::size_t products() const { return rows() * bands_.size() * (bands_.size() + 1) / 2; }
  std::size_t band_log_index(std::size_t r, std::size_t b) const {
    return spectra() + rows() * n_freq() + r * bands_.size() + b;
  }

  std::size_t sensors_;
  std::vector<std::string> names_;
  std::vector<double> frequency_;
  double df_, band_min_, band_max_;
  std::vector<spectral::Band> bands_;
  std::size_t extras_;
};

}  // namespace rollspec::scenes
