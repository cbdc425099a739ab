#pragma once
// Height statistics of line textures and surfaces (README Eq. 22-25).
//
//   mean m = <z>,  rms Rq = sqrt(<(z - m)^2>)  (about the mean, i.e. the standard deviation)
//   skewness = <(z - m)^3> / Rq^3,   kurtosis = <(z - m)^4> / Rq^4   (3 for a Gaussian, not excess)
//   autocorrelation (biased, mean removed, non-circular):
//       rho(tau) = sum_{i=0}^{N-1-tau} z'_i z'_{i+tau} / sum_i z'_i^2                 (Eq. 23)
//   correlation length = the lag where rho first falls to 1/e, interpolated linearly
//       between samples, times the spacing (m); NaN if rho never falls to 1/e       (Eq. 24)
//   surfaces: rho_x averages the row products over all rows (same for rho_y over columns).
//   radially averaged 2D PSD (periodic surface, no window), JJP 2017 normalisation:
//       C(q) = dx dy / (nx ny) |DFT(z - m)|^2,  variance = (2 pi)^-2 sum_q C(q) dqx dqy (Eq. 25)
//       averaged over the modes with |q| in [(b - 1/2) dq, (b + 1/2) dq), dq = max(dqx, dqy).
#include <cstddef>
#include <vector>

#include "kernels/texture/surface.hpp"

namespace rollspec::texture {

struct HeightStatistics {
  double mean = 0.0, rms = 0.0, skewness = 0.0, kurtosis = 0.0;
  double correlation_length_x = 0.0;  // m (the only one for a line)
  double correlation_length_y = 0.0;  // m (surfaces)
};

HeightStatistics line_statistics(const double* h, std::size_t n, double dx);
HeightStatistics surface_statistics(const Surface& s);
// Ensemble mean of per-realisation statistics (each field averaged; a correlation length that is
// NaN in some realisations is averaged over the others, NaN if it is NaN in all).
HeightStatistics mean_statistics(const std::vector<HeightStatistics>& per_realisation);
// Sample standard deviation (n - 1) over realisations of each field, with the same NaN rule; NaN
// for fewer than two values. Says how far one realisation strays from the mean.
HeightStatistics std_statistics(const std::vector<HeightStatistics>& per_realisation);

// rho(0..max_lag) of Eq. 23 by zero-padded FFT; the direct O(N max_lag) sum is the oracle.
std::vector<double> autocorrelation(const double* h, std::size_t n, std::size_t max_lag);
std::vector<double> autocorrelation_direct(const double* h, std::size_t n, std::size_t max_lag);
// Mean over rows (axis 0, lags along x) or columns (axis 1, lags along y) of the products, Eq. 23.
std::vector<double> surface_autocorrelation(const Surface& s, int axis, std::size_t max_lag);
double correlation_length_from_acf(const std::vector<double>& rho, double spacing);  // Eq. 24

// Periodogram of Eq. 25 on the half plane: value[iy * (nx/2+1) + ix] at qx = ix dqx,
// qy = (iy <= ny/2 ? iy : iy - ny) dqy.
std::vector<double> surface_periodogram(const Surface& s);

struct RadialPsd {
  std::vector<double> q;      // mean |q| of the modes in each bin, rad/m
  std::vector<double> psd;    // mean C over those modes, m^4
  std::vector<double> modes;  // number of modes (full plane) in each bin
  double dq = 0.0;
};
RadialPsd radially_averaged_psd(const Surface& s);

}  // namespace rollspec::texture
