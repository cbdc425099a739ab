#pragma once
// PSD of a roughness from measured short profiles (kernels/README.md (textures); seed 001 §3.1, seed 002 §4.2;
// README Eq. 15-17). Per profile of N samples at spacing dx:
//   1. remove the least-squares line a + b x (for a 2D map: the quadratic surface
//      a + b x + c y + d x^2 + e x y + f y^2 over the whole map)                      (Eq. 15)
//   2. optional 3-point median filter z_i <- median(z_{i-1}, z_i, z_{i+1}) (ends kept)
//   3. Hann-windowed periodogram, density-scaled so that sum_j G_j dk = variance:
//        G(k_j) = c_j dx |sum_i w_i z_i e^{-2 pi i j i / N}|^2 / (2 pi sum_i w_i^2),
//        k_j = 2 pi j / (N dx), c_j = 2 (1 at DC and Nyquist)                          (Eq. 16)
//      (the spectral kernel's D-15 with f_s = 1/dx in cycles/m, divided by 2 pi, Eq. 1)
//   4. average over the P >= 1 profiles: G = (1/P) sum_p G_p                         (Eq. 17)
// The estimate keeps the periodogram's level (no rescaling to the variance: README Eq. 42-43, the
// old Eq. 17b moved every octave by the share of the variance the window hides). Bins from
// first_resolved up are the resolved band; the variance below it is reported apart (Eq. 44):
//   V_r = sum_{j >= j_r} G_j dk,   V_u = max(0, V - V_r),   V = mean variance after steps 1-2.
// Profiles must share N and dx; spacing must be uniform (|dx_i / dx - 1| <= 1e-3).
#include <cstddef>
#include <vector>

#include "kernels/texture/surface.hpp"
#include "kernels/texture/tabulated_psd.hpp"

namespace rollspec::texture {

struct Profile {
  std::vector<double> x;  // positions, m, increasing and uniformly spaced
  std::vector<double> z;  // heights, m
};

// The lowest bin the estimate may resolve (README Eq. 42): the Hann main lobe spans bins j - 2 .. j + 2
// and the linear trend removal takes power from bins 1-2, so below 4 fundamentals the window and the
// trend decide the periodogram. Above it a bin is resolved once the variance below it, as the scan's
// longest wave, would leak at most kResolvedLeakage of the measured power into the octave it starts:
//   j_r = min { j >= 4 :  V_u(j) sum_{i=j}^{2j-1} L_i  <=  eps sum_{i=j}^{2j-1} G_i },
//   V_u(j) = max(0, V - sum_{i>=j} G_i dk),  L = longest_wave_leakage                     (Eq. 42)
constexpr std::size_t kFirstResolvedBin = 4;
constexpr double kResolvedLeakage = 0.05;  // eps: 0.2 dB

struct ProfilePsdOptions {
  bool median_filter = false;                          // step 2
  std::size_t first_resolved_bin = kFirstResolvedBin;  // the lowest j_r, >= 2 (Eq. 42)
  double resolved_leakage = kResolvedLeakage;          // eps of Eq. 42 (infinity: j_r = first_resolved_bin)
};

struct EstimatedPsd {
  std::vector<double> wavenumber;  // k_j = j dk, j = 0..N/2, rad/m
  std::vector<double> psd;         // G(k_j), m^3 (one-sided), Eq. 16-17; G_0 = 0 (the mean is no roughness)
  double dk = 0.0;                 // rad/m
  double spacing = 0.0;            // dx, m
  std::size_t samples = 0;         // N per profile
  std::size_t profiles = 0;        // P
  double sigma = 0.0;  // mean standard deviation of the profiles after steps 1-2, m (seed 001's sigma_meas, Eq. 10)
  double correlation_length =
      0.0;                // mean 1/e correlation length of those profiles (README Eq. 24), m; NaN if none reaches 1/e
  double variance = 0.0;  // V: mean variance of the profiles after steps 1-2, m^2
  std::size_t first_resolved = 1;  // j_r: the resolved band is bins j_r .. N/2 (Eq. 42)

  double resolved_variance() const;    // V_r = sum_{j >= j_r} G_j dk (Eq. 44)
  double unresolved_variance() const;  // V_u = max(0, V - V_r): longer waves than the scan resolves (Eq. 44)
};

// 1D profiles (step 1 with a line), one or more. Throws std::invalid_argument naming the profile and
// sample.
EstimatedPsd profile_psd(const std::vector<Profile>& profiles, const ProfilePsdOptions& options = {});

// A 2D height map: quadratic surface removed, then each row (along x) is one profile.
EstimatedPsd map_psd(const Surface& map, const ProfilePsdOptions& options = {});

// The raw estimate as a PSD table (bins j >= first_bin; the DC bin carries no roughness): a check.
// The generators take measured_line_psd (measured_psd.hpp): band-averaged, unresolved variance apart.
TabulatedPsd estimated_psd_table(const EstimatedPsd& estimate, Extension extension, std::size_t first_bin = 1);

// The steps, exposed for tests and for the engine's diagnostics.
void remove_linear_trend(std::vector<double>& z);  // least squares in the sample index
void remove_quadratic_surface(Surface& map);
void median_filter3(std::vector<double>& z);
// Eq. 16 for one profile (N >= 8), uniform spacing dx.
std::vector<double> hann_periodogram(const std::vector<double>& z, double dx);
// L_j of Eq. 42: the expected Eq. 16 periodogram, after the linear trend, of a wave of unit variance
// at bin 1 with a uniform random phase (the mean of its cosine and sine), m (m^2 per rad/m per m^2).
std::vector<double> longest_wave_leakage(std::size_t n, double dx);

}  // namespace rollspec::texture
