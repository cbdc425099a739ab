#pragma once
// Equivalent degrees of freedom of a third-octave band average (D-17) of a Welch estimate (D-15) of white
// Gaussian noise (kernels/spectral/README.md D-33c a; D-16 is its one-bin case). The band average
// P_b = (1/N_B) sum_s sum_k a_k |y_{s,k}|^2 (a_k: the band's bin weights times the one-sided factor) is a
// quadratic form in the Gaussian samples, so by Isserlis' theorem, with unit noise variance,
//   E P_b   = sum_k a_k G_0(k, k),
//   var P_b = (1/N_B^2) sum_{|m| < N_B} (N_B - |m|) sum_{k,k'} a_k a_k' (|G_m(k, k')|^2 + |P_m(k, k')|^2),
//   G_m(k, k') = sum_t u_k(t) conj(u_k'(t - m S)),   P_m(k, k') = sum_t u_k(t) u_k'(t - m S),
//   u_k(t) = w_t e^{-2 pi i k t / L} - W_k / L   (the segment's mean removed; W_k = sum_t w_t e^{-2 pi i k t / L}),
// and nu_b = 2 (E P_b)^2 / var P_b (the scaled chi-square with the same two moments). Where W_k = 0 (every bin
// outside the window's main lobe at DC) |G_m(k, k')| = |R_m(k - k')| and |P_m(k, k')| = |R_m(k + k')|, R_m the
// DFT of the window products w_t w_{t - m S}: one FFT per lag; the few bins with W_k != 0 are summed directly.
#include <cstddef>
#include <vector>

#include "kernels/spectral/welch.hpp"

namespace rollspec::spectral {

// The bins of a band [lower, upper] Hz on a grid of step df with n bins, by band_average's rule: bin k covers
// [k - 1/2, k + 1/2] df and weighs its overlap with the band over the band's width.
struct BandWeights {
  std::size_t first = 0;       // the first bin with a weight
  std::vector<double> weight;  // bins first, first + 1, ...
};
BandWeights band_weights(std::size_t n, double df, double lower, double upper);

class BandDof {
 public:
  explicit BandDof(const WelchConfig& config);
  // nu_b of the band average over [lower, upper] Hz of the Welch estimate of `samples` samples of white Gaussian
  // noise; 0 when samples < L or no bin lies in the band.
  double operator()(std::size_t samples, double lower, double upper) const;
  // The same Isserlis sums for two bands, a_k of [lower_b, upper_b] and a_k' of [lower_c, upper_c] (D-33e):
  // sum_{|m| < N_B} (N_B - |m|) sum_{k,k'} a_k a_k' (|G_m(k, k')|^2 + |P_m(k, k')|^2) / N_B^2, the covariance of the
  // two band averages of unit white noise before the density's scale (var P_b for b = c); 0 when samples < L.
  double pair_sum(std::size_t samples, double lower_b, double upper_b, double lower_c, double upper_c) const;
  // sum_k a_k G_0(k, k) of [lower, upper]: E P_b of unit white noise before the density's scale.
  double mean_sum(double lower, double upper) const;

 private:
  WelchConfig config_;
  std::vector<double> window_;
  std::vector<std::vector<double>> r2_;  // |R_m(j)|^2, j = 0..L/2, for each lag m with m S < L
  std::vector<bool> lobe_;               // bins 0..L/2 whose kernel the mean's removal changes (W_k != 0)
};

// The same moments with every G_m, P_m summed directly over the segment (O(bins^2 L) per lag): the reference.
double band_dof_reference(const WelchConfig& config, std::size_t samples, double lower, double upper);

}  // namespace rollspec::spectral
