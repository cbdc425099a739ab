#pragma once
// The shape and coordinates of an ensemble scene's /psd and /bands, known from its settings before
// anything runs: a sweep stacks its points into one array, so a swept key that changes them is
// refused by `plan` and `run` before the first point instead of after the second.
#include <string>
#include <vector>

#include "kernels/spectral/welch.hpp"

namespace rollspec::scenes {

struct ResultShape {
  std::vector<std::string> rows;               // /psd/sensor (and /bands/sensor)
  std::vector<double> frequency;               // /psd/frequency
  std::vector<double> band_lower, band_upper;  // /bands/lower_frequency, upper_frequency

  bool operator==(const ResultShape& o) const;
  bool operator!=(const ResultShape& o) const { return !(*this == o); }
  // "/psd/mean 1 x 513 (0 .. 512 Hz), /bands/level_db 1 x 17 (8.91 .. 447 Hz)"
  std::string text() const;
};

// The layout PsdRows gives the sensors (with their mean row when asked and there are several),
// the Welch estimator's bins and the third-octave bands between band_min and band_max.
ResultShape psd_result_shape(std::vector<std::string> sensors, bool sensor_mean, const spectral::WelchConfig& welch,
                             double band_min, double band_max);

// "sensor_1", ..., "sensor_n": the row names of scenes with numbered sensors.
std::vector<std::string> numbered_sensors(std::size_t n);

}  // namespace rollspec::scenes
