#pragma once
// What a result's intervals include besides the realisations' scatter: a contact table's own
// sampling error, by a leave-one-surface-out jackknife ([stiffness] table_error = jackknife,
// kernels/spectral/README.md D-30). The ensemble runs once with the full table (the result's
// central values) and once with each of its N sub-tables on the same realisation streams; the
// jackknife variance of each bin's and band's level (dB) over the N runs widens that bin's or
// band's interval on each side (D-30b), less the part of it that is the runs' own sampling noise,
// measured from the same realisations paired across the runs (D-30c).
#include <cstdint>
#include <string>
#include <vector>

namespace rollspec::io {

struct PsdEnsemble;

struct TableError {
  std::uint64_t surfaces = 0;         // N (0: the intervals are conditional on the table)
  std::vector<double> bin_variance;   // rows x frequency, dB^2 (NaN where a bin has no power in some run)
  std::vector<double> band_variance;  // rows x bands, dB^2
  std::vector<double> bin_noise;      // what D-30c removed from the jackknife, dB^2 (NaN: nothing)
  std::vector<double> band_noise;
  std::string table;  // the table the intervals are conditional on ("": none)
};

// Band levels (dB) of e, rows x bands, as /bands/level_db holds them.
std::vector<double> band_levels_db(const PsdEnsemble& e);

// What the combined run of the N sub-tables keeps besides their spectra (D-30c), over the leading
// linear values (rows x bins, then rows x bands): each run's mean over the K realisations, and
// q = sum_r sum_i (x_ir - mean over the runs of x_.r)^2.
struct PairedSums {
  std::uint64_t realisations = 0;          // K
  std::vector<double> q;                   // bins, then bands
  std::vector<std::vector<double>> means;  // [run][bins, then bands]
};

// The table's variances from the N sub-table ensembles (their spectra; same rows, bins, bands):
// the jackknife (D-30a) less the runs' own noise (D-30c), at least 0.
TableError table_jackknife(const std::vector<PsdEnsemble>& sub_tables, const PairedSums& paired,
                           const std::string& table);

// The sentence /psd@interval_includes and /bands@interval_includes hold.
std::string interval_includes(const TableError& t);

// Widens the bin interval [lo, hi] of a bin of mean `mean` (linear units), or the band interval
// [lo, hi] of level `level` (dB), by variance v (dB^2) of a table over `t.surfaces` (D-30b); K
// realisations, confidence `level_p`. Unchanged where v is not finite or there is no interval.
void widen_bin_interval(double mean, double& lo, double& hi, double v, std::uint64_t surfaces, std::uint64_t K,
                        double level_p);
void widen_band_interval(double level, double& lo, double& hi, double v, std::uint64_t surfaces, std::uint64_t K,
                         double level_p);

}  // namespace rollspec::io
