#pragma once
// Intervals of an ensemble mean from the realisations' own scatter (kernels/spectral/README.md
// D-21, D-22). Realisations are independent and identically distributed; nothing inside one
// realisation is (adjacent Welch bins and segments of a moving-load record are correlated), so
// every interval takes its width from the sample moments of the K per-realisation values, never
// from a count of bins or segments.
//
// One realisation's PSD value is modelled two ways, and the interval is the union of the two, so
// that it holds under either: a scaled chi-square (gamma) law, right for Welch averages of a
// stationary record, and a lognormal law, right for records whose power varies over orders of
// magnitude between realisations (intermittent contact, impacts). Both carry t_{K-1} for the
// estimated spread. Below kMinRealisationsForInterval no interval is given: [0, +inf), dof 0.
#include <cstdint>

namespace rollspec::spectral {

inline constexpr std::uint64_t kMinRealisationsForInterval = 5;

// Sample moments over K realisations of one value x and of ln x (standard deviations with K - 1).
struct Scatter {
  double mean = 0.0, std_dev = 0.0;
  double log_mean = 0.0, log_std = 0.0;  // of ln x; log_std NaN or inf when some x <= 0
};

struct ScatterInterval {
  double lower = 0.0;  // multiply the mean by this for the lower bound
  double upper = 0.0;  // ... for the upper bound (+inf when no interval exists)
  double dof = 0.0;    // Satterthwaite dof of the mean, 2 K mean^2 / std^2 (D-21a); 0: no interval
  bool defined() const { return dof > 0.0; }
};

// Interval for the expectation of the ensemble mean (D-21). `level` in (0, 1).
ScatterInterval mean_interval(const Scatter& s, std::uint64_t realisations, double level);

// Prediction interval for the mean of `records` (>= 1) further independent records, each
// distributed like one realisation: what a measurement averaged over them may read (D-22).
ScatterInterval prediction_interval(const Scatter& s, std::uint64_t realisations, double records, double level);

}  // namespace rollspec::spectral
