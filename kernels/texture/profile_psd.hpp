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
//   4. average over the P profiles: G = (1/P) sum_p G_p                              (Eq. 17)
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

struct ProfilePsdOptions {
  bool median_filter = false;  // step 2
};

struct EstimatedPsd {
  std::vector<double> wavenumber;  // k_j = j dk, j = 0..N/2, rad/m
  std::vector<double> psd;         // G(k_j), m^3 (one-sided)
  double dk = 0.0;                 // rad/m
  double spacing = 0.0;            // dx, m
  std::size_t samples = 0;         // N per profile
  std::size_t profiles = 0;        // P
  double sigma = 0.0;  // mean standard deviation of the profiles after steps 1-2, m (seed 001's sigma_meas, Eq. 10)
  double correlation_length =
      0.0;  // mean 1/e correlation length of those profiles (README Eq. 24), m; NaN if none reaches 1/e
};

// 1D profiles (step 1 with a line). Throws std::invalid_argument naming the profile and sample.
EstimatedPsd profile_psd(const std::vector<Profile>& profiles, const ProfilePsdOptions& options = {});

// A 2D height map: quadratic surface removed, then each row (along x) is one profile.
EstimatedPsd map_psd(const Surface& map, const ProfilePsdOptions& options = {});

// The estimate as a PSD table (bins j >= first_bin; the DC bin carries no roughness), so measured
// profiles feed the line and surface generators. Bins below ~8 profile fundamentals are biased by
// the window and the trend removal (README, test of Eq. 15-17); first_bin can skip them.
TabulatedPsd estimated_psd_table(const EstimatedPsd& estimate, Extension extension, std::size_t first_bin = 1);

// The steps, exposed for tests and for the engine's diagnostics.
void remove_linear_trend(std::vector<double>& z);  // least squares in the sample index
void remove_quadratic_surface(Surface& map);
void median_filter3(std::vector<double>& z);
// Eq. 16 for one profile (N >= 8), uniform spacing dx.
std::vector<double> hann_periodogram(const std::vector<double>& z, double dx);

}  // namespace rollspec::texture
