#pragma once
// The spectral part of a result file, shared by every scene (schema 1):
//   /psd/frequency (Hz, scale "frequency"), /psd/sensor (names, scale "sensor"),
//   /psd/mean, /psd/ci_lower, /psd/ci_upper, /psd/std   (sensor x frequency, PSD unit)
//   /bands/centre_frequency (Hz, scale "band"), /bands/nominal_frequency, /bands/lower_frequency,
//   /bands/upper_frequency, /bands/level_db, /bands/ci_lower_db, /bands/ci_upper_db (sensor x band),
//   /bands/degrees_of_freedom (band)
// The interval is chi-square (theory D-16) with nu = K * nu_Welch per bin, and per band
// nu_band = max(nu_bin, min(nu_bin * B / (df * ENBW), 2 B T)) for B the band width and T the
// record time behind the mean (D-17: bins closer than the window's noise bandwidth are
// correlated, and no estimate holds more than the 2 B T degrees of freedom of the record,
// Bendat & Piersol 2010 §8.5).
#include <cstdint>
#include <string>
#include <vector>

namespace rollspec::io {

class Hdf5Writer;

struct PsdEnsemble {
  std::vector<double> frequency;       // Hz, uniform from 0
  std::vector<std::string> sensors;
  std::vector<double> mean;            // sensors x frequency
  std::vector<double> std_dev;         // ensemble standard deviation of one realisation's PSD
  std::uint64_t realisations = 0;
  double dof_per_bin = 0.0;            // of the ensemble mean
  double window_enbw_bins = 1.5;
  double record_seconds = 0.0;         // total analysed time behind the mean (all realisations)
  double confidence = 0.95;
  double band_min = 0.0, band_max = 0.0;  // Hz
  std::string units = "(m/s^2)^2/Hz";
  std::string quantity = "acceleration";
  // Per-bin dof from the realisations' scatter (Satterthwaite): nu_i = min(dof_per_bin,
  // 2 K mean_i^2 / std_i^2), for scenes whose realisations differ by more than Welch noise
  // (intermittent contact, impacts). Band levels then take the mean nu_i over the band's bins
  // (bins of one realisation rise and fall together, so averaging them gains nothing).
  bool empirical_dof = false;
};

void write_psd_result(Hdf5Writer& w, const PsdEnsemble& e);

// Coordinate scales of a group: <group>/frequency (Hz) and <group>/sensor (names). Dimension
// scales are visible only in their own group and below (netCDF semantics, which xarray's
// h5netcdf engine follows), so every group with spectra carries its own.
void write_frequency_scale(Hdf5Writer& w, const std::string& group, const std::vector<double>& frequency);
void write_sensor_scale(Hdf5Writer& w, const std::string& group, const std::vector<std::string>& sensors);

// Band degrees of freedom from the per-bin value (D-17).
double band_dof(double dof_per_bin, double band_width, double df, double enbw_bins, double record_seconds);

}  // namespace rollspec::io
