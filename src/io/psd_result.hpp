#pragma once
// The spectral part of a result file, shared by every scene (schema 2):
//   /psd/frequency (Hz, scale "frequency"), /psd/sensor (names, scale "sensor"),
//   /psd/mean, /psd/ci_lower, /psd/ci_upper, /psd/std, /psd/degrees_of_freedom (sensor x frequency)
//   /bands/centre_frequency (Hz, scale "band"), /bands/nominal_frequency, /bands/lower_frequency,
//   /bands/upper_frequency (band), /bands/level_db, /bands/ci_lower_db, /bands/ci_upper_db,
//   /bands/std, /bands/log_std, /bands/degrees_of_freedom (sensor x band),
//   /bands/log_level_covariance (sensor x band x band)
//   /psd/sensor_position, /bands/sensor_position (m, on the sensor scale; NaN for sensor_mean): an
//   auxiliary coordinate, named by the group attribute `coordinates` (xarray shows it beside the names)
// Every interval comes from the realisations' own scatter (kernels/spectral D-21): realisations
// are independent, nothing inside one is (adjacent Welch bins, segments of a moving-load record).
// The band interval uses the scatter of each realisation's band average, not a count of bins;
// /bands/std and /bands/log_std let `rollspec compare` predict a measurement's scatter (D-22);
// /bands/log_level_covariance gives its combined test over bands (D-26).
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/spectral/ensemble_interval.hpp"
#include "kernels/spectral/tail_check.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/io/table_error.hpp"

namespace rollspec::io {

class Hdf5Writer;

struct PsdEnsemble {
  std::vector<double> frequency;                // Hz, uniform from 0
  std::vector<std::string> sensors;             // rows
  std::vector<double> sensor_position;          // m, per sensor; rows past it (sensor_mean) have none
  std::string position_meaning;                 // long_name of sensor_position (empty: no positions)
  std::vector<double> mean;                     // rows x frequency
  std::vector<double> std_dev;                  // ensemble standard deviation of one realisation's PSD
  std::vector<spectral::Scatter> scatter;       // rows x frequency: moments of x and ln x
  std::vector<spectral::Scatter> band_scatter;  // rows x bands: of the realisations' band averages
  std::vector<double> band_log_covariance;      // rows x bands x bands, of ln band average (empty: not kept)
  std::vector<spectral::TailCheck> band_tail;   // rows x bands: is K enough for the interval (D-29; empty: no check)
  std::uint64_t realisations = 0;
  double welch_dof = 0.0;  // K x the Welch dof (D-16) of a stationary record: information only
  // The estimator each realisation's record went through, so that a measurement can go through the same
  // one (`rollspec compare RESULT RECORDING`): /psd@sample_rate, welch_segment, welch_overlap,
  // welch_window, record_samples. sample_rate 0: not written.
  spectral::WelchConfig welch{0.0, 0, 0, spectral::Window::hann, spectral::Detrend::constant};
  std::size_t record_samples = 0;
  double window_enbw_bins = 1.5;
  double confidence = 0.95;
  double band_min = 0.0, band_max = 0.0;  // Hz
  std::string units = "(m/s^2)^2/Hz";
  std::string quantity = "acceleration";
  TableError table_error;  // a table's own error the intervals include, or the table they are conditional on
  // Non-empty: the realisations do not sample what varies (every one rolls over the same strip), so no
  // interval is given, and this says why (the interval_method text and run's note).
  std::string no_interval;
};

void write_psd_result(Hdf5Writer& w, const PsdEnsemble& e);

// /reference/psd: a scene's exact answer for the one row of `e` (its frequencies, sensor and units), labelled
// "exact", on /reference's own scales.
void write_exact_reference(Hdf5Writer& w, const PsdEnsemble& e, const std::vector<double>& exact,
                           const std::string& long_name);

// The third-octave bands of a result: those inside [max(band_min, df), min(band_max, f_max)].
std::vector<spectral::Band> result_bands(const std::vector<double>& frequency, double band_min, double band_max);

// How the intervals were made, as stored in the /psd attribute interval_method (`no_interval`: why
// there are none although K would allow them).
std::string interval_method(std::uint64_t realisations, const std::string& no_interval = "");

// Coordinate scales of a group: <group>/frequency (Hz) and <group>/sensor (names). Dimension
// scales are visible only in their own group and below (netCDF semantics, which xarray's
// h5netcdf engine follows), so every group with spectra carries its own.
void write_frequency_scale(Hdf5Writer& w, const std::string& group, const std::vector<double>& frequency);
void write_sensor_scale(Hdf5Writer& w, const std::string& group, const std::vector<std::string>& sensors);

// <group>/sensor_position (m) on the sensor scale of `rows` rows, NaN past the positions given; named
// as a coordinate by the group attribute `coordinates` (CF, read by xarray's decoder).
void write_sensor_positions(Hdf5Writer& w, const std::string& group, const std::vector<double>& positions,
                            std::size_t rows, const std::string& long_name);

}  // namespace rollspec::io
