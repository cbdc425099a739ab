#pragma once
// What a result's intervals include besides the realisations' scatter: a contact table's own
// sampling error, by a leave-one-surface-out jackknife ([stiffness] table_error = jackknife,
// kernels/spectral/README.md D-30). The ensemble runs once with the full table (the result's
// central values) and once with each of its N sub-tables on the same realisation streams; the
// jackknife variance of each bin's and band's level (dB) over the N runs widens that bin's or
// band's interval on each side (D-30b). The part of it that is the runs' own sampling noise is
// measured from the same realisations paired across the runs (D-30c) and reported beside it.
#include <cstdint>
#include <string>
#include <vector>

namespace rollspec::io {

struct PsdEnsemble;

struct TableError {
  std::uint64_t surfaces = 0;         // N (0: the intervals are conditional on the table)
  std::vector<double> bin_variance;   // the jackknife, rows x frequency, dB^2 (NaN: a bin without power in some run)
  std::vector<double> band_variance;  // rows x bands, dB^2
  std::vector<double> bin_noise;      // the part of it that is the runs' own noise (D-30c), dB^2 (NaN: unknown)
  std::vector<double> band_noise;
  std::vector<double> band_levels;  // the N sub-table runs' band levels, N x (rows x bands), dB: the term's
                                    // band-by-band covariance for compare and fit (D-31)
  double dof = 0.0;                 // nu_T of the variances: N - 1, fewer over overlapping Welch segments (D-30d)
  double variance_factor = 1.0;     // applied to the jackknife: 1, or 2 N / nu_Welch over overlapping segments (D-30d)
  std::string table;                // the table the intervals are conditional on ("": none)
  std::string unit = "surfaces";    // what the jackknife left out one at a time (surfaces, strips)
  std::string noise_warning;        // non-empty when the term is mostly the runs' own noise (table_noise_warning)
  bool independent_bands = false;   // D-31c: only each band's variance is the table's term across bands
  std::uint64_t realisations = 0;   // K_J, the sub-table runs' realisations (D-30f: may exceed the run's K)
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

// The table's variances from the N sub-table ensembles (their spectra; same rows, bins, bands): the
// jackknife (D-30a), and the runs' own noise in it (D-30c).
// Overlapping units (Welch segments of one path, D-30d) scale both by `variance_factor` and give the
// widening `dof` degrees of freedom; independent ones leave 1 and N - 1 (dof 0 means N - 1).
TableError table_jackknife(const std::vector<PsdEnsemble>& sub_tables, const PairedSums& paired,
                           const std::string& table, const std::string& unit, double variance_factor = 1.0,
                           double dof = 0.0);

// The runs' own noise against the table's part, n / (V_J - n), median over the bands (D-30c): +inf
// where the term is all noise, 0 without bands.
double median_noise_ratio(const TableError& t);

// When more than half of the jackknife is the runs' own noise (D-30c, median over the bands), the
// term is mostly that noise (realisations chaotic in the table) and the intervals are wider than the
// table's error alone needs: the sentence that says so, with the K that would bring the noise to a
// quarter of the table's term (the noise falls as 1/K). Empty otherwise.
std::string table_noise_warning(const TableError& t, std::uint64_t K);

// The sentence /psd@interval_includes and /bands@interval_includes hold.
std::string interval_includes(const TableError& t);

// Widens the bin interval [lo, hi] of a bin of mean `mean` (linear units), or the band interval
// [lo, hi] of level `level` (dB), by variance v (dB^2) of `table_dof` degrees of freedom (D-30b); K
// realisations, confidence `level_p`. Unchanged where v is not finite or there is no interval.
void widen_bin_interval(double mean, double& lo, double& hi, double v, double table_dof, std::uint64_t K,
                        double level_p);
void widen_band_interval(double level, double& lo, double& hi, double v, double table_dof, std::uint64_t K,
                         double level_p);

}  // namespace rollspec::io
