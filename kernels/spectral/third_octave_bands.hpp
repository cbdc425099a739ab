#pragma once
// IEC 61260-1 base-ten one-third-octave bands (theory D-17):
//   f_m(x) = 1000 * 10^(x/10) Hz,  f_1,2 = f_m * 10^(-/+1/20),  x integer band index.
// Band level = mean of the one-sided PSD over [f_1, f_2] (a density, same unit as the PSD), with
// each bin k taken to cover [f_k - df/2, f_k + df/2] and weighted by its overlap with the band.
#include <cstddef>
#include <vector>

namespace rollspec::spectral {

struct Band {
  int index;       // x in f_m = 1000 * 10^(x/10)
  double centre;   // Hz, exact base-ten midband frequency
  double lower;    // Hz
  double upper;    // Hz
  double nominal;  // Hz, the IEC nominal label (e.g. 1250 for x = 1)
};

Band third_octave_band(int index);

// All bands whose edges lie inside [f_min, f_max].
std::vector<Band> third_octave_bands(double f_min, double f_max);

// Mean PSD over [lower, upper] for a PSD sampled at f_k = k df (k = 0..n-1).
double band_average(const double* psd, std::size_t n, double df, double lower, double upper);

// Mean over [lower, upper] of a PSD given on any increasing frequency grid f[0..n), integrating
// its piecewise-linear interpolant. Returns NaN when the grid does not cover the band.
double band_average_irregular(const double* f, const double* psd, std::size_t n, double lower, double upper);

// ln of the ratio of one PSD's band means by the two rules above, on the grid f_k = k df:
// band_average_irregular (a measurement's rule: its points joined linearly) over band_average (the
// engine's: each bin flat over [k - 1/2, k + 1/2] df). Near 0 where the band spans many bins; a band
// of a bin or two beside a steep slope reads differently by the two (kernels/spectral D-27h).
double band_rule_shift(const double* psd, std::size_t n, double df, double lower, double upper);

// Number of bins (fractional, by overlap) that a band covers.
double band_bins(double df, double lower, double upper);

}  // namespace rollspec::spectral
