#pragma once
// One row (a sensor or the sensor mean) of a result's third-octave bands, as `rollspec compare`
// reads it: levels, the interval of the simulated mean, and the realisations' scatter of their
// band averages, from which a measurement's prediction interval follows (kernels/spectral D-22).
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/io/hdf5_file.hpp"

namespace rollspec::io {

struct BandLevels {
  std::string sensor;                         // the row's name in /bands/sensor
  double position = NAN;                      // m, from /bands/sensor_position (NaN: none, or sensor_mean)
  std::string pick_note;                      // how --measured-position chose the row (empty: by name)
  std::vector<double> nominal, lower, upper;  // Hz
  std::vector<double> level_db, ci_lower_db, ci_upper_db;
  std::vector<double> std_dev;         // of one realisation's band average, PSD unit
  std::vector<double> log_std;         // of its natural log
  std::vector<double> log_skewness;    // G1 of its natural log (D-26d; empty: not in the file)
  std::vector<double> log_covariance;  // band x band, between-band covariance of the logs (empty: not in the file)
  std::uint64_t realisations = 0;
  double confidence = 0.95;
  std::string interval_method;
  // The table's own error (kernels/spectral D-30, D-31): the N leave-one-out sub-table runs' levels of
  // this row, N x bands (empty: the result's table is not random, or its error was not estimated).
  std::vector<double> table_levels_db;
  std::size_t table_units = 0;           // N
  double table_dof = 0.0;                // nu_T
  double table_variance_factor = 1.0;    // D-30d
  std::string table;                     // the table the term is of, as /bands@interval_includes says
  bool table_independent_bands = false;  // D-31c: the term's covariance is diagonal (/bands@table_covariance)
  // The result's table is random but its error was not estimated (/bands@interval_includes says the
  // intervals are conditional on it): a verdict cannot carry it.
  bool table_error_missing = false;
  std::string point;  // the sweep point read ("section.key=value, ..."; "" for a result that is no sweep)
};

// The table term's covariance between the bands `band` (indices into b), in (natural log)^2: the
// jackknife (D-30a) of the sub-table runs' levels times the variance factor (D-30d), its diagonal only
// where the bands' errors are independent (D-31c). Row-major p x p; empty when b has no table term.
std::vector<double> table_log_covariance(const BandLevels& b, const std::vector<std::size_t>& band);

// D-31e: the intensity lambda by which a full table term's correlations between the bands `band` shrink toward
// its diagonal, from the N sub-table runs' levels (Schaefer-Strimmer); 0 where the term is diagonal already
// (D-31c) or there is none. Every user of the full term (test, level offset, fit) shrinks it by this lambda.
double table_shrinkage(const BandLevels& b, const std::vector<std::size_t>& band);

// How a command picks its row: --sensor (a name from /bands/sensor, or K of sensor_K) or
// --measured-position X (m: the sensor nearest X in /bands/sensor_position); neither picks
// "sensor_mean" when the result has it, else the first row.
struct SensorChoice {
  std::string name;
  std::optional<double> position;
};

// The choice of --sensor and --measured-position, refused (exit 64) before any work when both are
// given or the position is not a finite number.
SensorChoice sensor_choice(const std::string& name, std::optional<double> position);

// Refuses (exit 64) an unknown sensor, naming the ones there are, a position with no sensor near it or a result without
// positions, and (exit 65) datasets of the wrong shape or with NaN. `point` picks one point of a sweep result
// (src/io/sweep_point.hpp: K, or section.key=value[,...]); a sweep result without it, or a point for a result
// that is no sweep, is refused (exit 64) naming the points there are.
BandLevels read_band_levels(const Hdf5Reader& r, const SensorChoice& choice, const std::string& point = "");

}  // namespace rollspec::io
