#pragma once
// Seed line-sum surfaces (kernels/README.md D-4; seed 001 §3.1, Eq. 9-10; README Eq. 29-32).
//
// Rows d (line textures along x, one per y index) and columns g (line textures along y, one
// per x index), box lengths n, m (samples, the seed's "correlation lengths"):
//   z_ij = sum_{k=i}^{i+n-1} sum_{l=j}^{j+m-1} (d_kl + g_lk) / 2,  i < nx, j < ny        (Eq. 29, seed Eq. 9)
//   Z_ij = (z_ij - mean z) sigma / sigma_z                                                (Eq. 30, seed Eq. 10)
// (the mean is removed so that rms = standard deviation = sigma exactly).
// d holds ny + m - 1 lines of nx + n - 1 samples; g holds nx + n - 1 lines of ny + m - 1.
//
// The realised correlation length is not n: with R_x, R_y the line autocovariances at integer
// lags, the expected autocovariance of z along x is
//   4 R_z(tau, 0) = m sum_{|s|<n} (n - |s|) R_x(tau + s) + (n - |tau|)_+ sum_{|s|<m} (m - |s|) R_y(s)   (Eq. 31)
// (and symmetrically along y). seed_box_lengths() picks the integers n, m whose Eq. 31 puts the
// 1/e point (statistics.hpp, Eq. 24) closest to the requested correlation lengths (Eq. 32).
#include <cstddef>
#include <memory>
#include <vector>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/psd.hpp"
#include "kernels/texture/surface.hpp"

namespace rollspec::texture {

struct SeedSurfaceSpec {
  std::size_t nx = 0, ny = 0;        // output grid
  double dx = 0.0, dy = 0.0;         // m
  std::size_t box_x = 1, box_y = 1;  // n, m (samples)
  double sigma = 0.0;                // requested rms height (the seed's sigma_meas), m
};

// Eq. 29-30 with prefix sums, O(nx ny); the quadruple loop is the oracle.
Surface seed_surface(const SeedSurfaceSpec& spec, const std::vector<double>& d, const std::vector<double>& g);
Surface seed_surface_direct(const SeedSurfaceSpec& spec, const std::vector<double>& d, const std::vector<double>& g);

// Line autocovariance R(s dx), s = 0..max_lag, of a line synthesised from G at harmonics j dk:
// R(s) = sum_j G_j dk cos(j dk s dx).
std::vector<double> line_autocovariance(const LineTextureGenerator& lines, std::size_t max_lag);

// Expected correlation lengths (m) of Eq. 31 for given box lengths; rx, ry from line_autocovariance.
struct SeedCorrelation {
  double x = 0.0, y = 0.0;
};
SeedCorrelation seed_expected_correlation(const std::vector<double>& rx, const std::vector<double>& ry, std::size_t n,
                                          std::size_t m, double dx, double dy);

struct SeedBoxLengths {
  std::size_t box_x = 1, box_y = 1;
  SeedCorrelation expected;  // Eq. 31 at the chosen n, m
};
SeedBoxLengths seed_box_lengths(const std::vector<double>& rx, const std::vector<double>& ry, double dx, double dy,
                                double correlation_x, double correlation_y);

// The whole seed method from one line PSD: lines along x (spacing dx) and y (spacing dy) from
// `psd` with a common synthesis period (so Eq. 31 holds for every n, m), box lengths from the
// requested correlation lengths, then Eq. 29-30.
struct SeedSurfaceRequest {
  std::size_t nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;
  double correlation_x = 0.0, correlation_y = 0.0;  // m, 1/e definition (Eq. 24)
  double sigma = 0.0;                               // m
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;
  std::size_t max_box = 0;  // largest n or m tried; 0: min(nx, ny)
  bool allow_truncation = false;
};

class SeedSurfaceGenerator {
 public:
  SeedSurfaceGenerator(const Psd& psd, const SeedSurfaceRequest& request);

  const SeedSurfaceSpec& spec() const { return spec_; }
  const SeedBoxLengths& box() const { return box_; }
  // U(0,1) numbers one realisation consumes: for each d line then each g line, a phase array
  // then an amplitude array of that line generator's harmonics().
  std::size_t random_count() const;
  void generate(const double* u, Surface& out) const;

 private:
  SeedSurfaceSpec spec_;
  SeedBoxLengths box_;
  std::unique_ptr<LineTextureGenerator> along_x_, along_y_;
};

}  // namespace rollspec::texture
