#pragma once
// Smoothing of a PSD estimated from measured profiles before it feeds surfaces (README Eq. 33-35).
//
// The averaged periodogram of P profiles (Eq. 16-17) scatters by about 1/sqrt(P) from bin to bin.
// The inverse Abel transform of Eq. 19 weights the slope G' near q = r by 1/sqrt(q^2 - r^2), so
// this scatter becomes large positive and negative swings of C_iso, and clamping the negative
// ones (Eq. 19-20) adds power: surfaces from the raw estimate come out 1.6-2x too rough.
// Averaging the bins in log-spaced bands (at least `min_bins` per band) keeps the band power
//   G_b = (1/M_b) sum_{j in b} G_j,   G_b M_b dk = sum_{j in b} G_j dk                      (Eq. 33)
// exactly, so the table's variance is that of the estimate, while the scatter drops to about
// 1/sqrt(P M_b / 1.94) (Hann bins are correlated). The bands split the octaves of bins
// [f 2^m, f 2^{m+1}) (f = first_bin) into up to `bands_per_octave` geometric parts of at least
// min_bins bins each, so every such octave keeps its measured power exactly.
#include <cstddef>
#include <vector>

#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/tabulated_psd.hpp"

namespace rollspec::texture {

struct PsdBands {
  std::size_t bands_per_octave = 3;  // band width in log k (wider where min_bins asks for it)
  std::size_t min_bins = 4;          // periodogram bins per band at least
  std::size_t first_bin = 1;         // bins below carry no roughness (DC) or are biased (Eq. 15)
};

struct BandAveragedPsd {
  std::vector<std::size_t> first, last;  // bins [first_b, last_b] of band b
  std::vector<double> centre;            // sqrt((first_b - 1/2)(last_b + 1/2)) dk, rad/m (Eq. 34)
  std::vector<double> psd;               // G_b of Eq. 33, m^3
};

// Eq. 33 over bins first_bin..N/2 of the estimate. Throws std::invalid_argument if fewer than
// 2 bands fit.
BandAveragedPsd band_averaged_psd(const EstimatedPsd& estimate, const PsdBands& bands = {});

// The band averages as a log-log table (Eq. 35): nodes at the band centres, plus the first band's
// lower edge (f_0 - 1/2) dk and the Nyquist wavenumber carrying the end bands' values; the nodes are
// scaled (Eq. 41) until the table's integral over every band is that band's power, so the table
// holds the estimate's variance exactly however steep the spectrum. Use its to_psd() with
// cell_average (Eq. 14b) so that a synthesis grid keeps it too.
TabulatedPsd smoothed_psd_table(const EstimatedPsd& estimate, Extension extension, const PsdBands& bands = {});

}  // namespace rollspec::texture
