#pragma once
// Shared helpers of the texture tests: U(0,1) draws (a local mt19937_64 stands in for the
// engine's Philox streams, tests only), exact-harmonic periodograms, third-octave band means and the
// line PSD the Abel-pair tests project.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/isotropic_psd.hpp"
#include "kernels/texture/self_affine_psd.hpp"

namespace texture_test {

// n numbers in (0, 1]: -ln u must stay finite for Rayleigh amplitudes.
inline std::vector<double> uniforms(std::mt19937_64& rng, std::size_t n) {
  std::vector<double> u(n);
  for (double& v : u) v = 1.0 - std::generate_canonical<double, 53>(rng);
  return u;
}

// One-sided periodogram per rad/m of a full-period sequence (rectangular window, D-15 / 2 pi):
// exact at the synthesis harmonics.
inline std::vector<double> periodogram(const std::vector<double>& h, double dx) {
  rollspec::spectral::WelchConfig cfg;
  cfg.sample_rate = 1.0 / dx;
  cfg.segment = h.size();
  cfg.overlap = 0;
  cfg.window = rollspec::spectral::Window::rectangular;
  cfg.detrend = rollspec::spectral::Detrend::none;
  const rollspec::spectral::WelchPlan plan(cfg);
  rollspec::spectral::WelchWorkspace ws(cfg.segment);
  std::vector<double> g(plan.n_freq());
  plan.psd(h.data(), h.size(), g.data(), ws);
  for (double& v : g) v /= 2.0 * M_PI;
  return g;
}

inline double db(double ratio) { return 10.0 * std::log10(ratio); }

struct BandCompare {
  double centre_n;  // cycles/m
  double bins;      // harmonics in the band
  double delta_db;  // 10 log10(estimate / target)
};

// Third-octave bands of spatial frequency n = k / 2 pi over [n_lo, n_hi] holding >= min_bins
// harmonics of spacing dn; band means of estimate and target (both sampled at j dn).
inline std::vector<BandCompare> compare_bands(const std::vector<double>& estimate, const std::vector<double>& target,
                                              double dn, double n_lo, double n_hi, double min_bins) {
  std::vector<BandCompare> out;
  for (const auto& b : rollspec::spectral::third_octave_bands(n_lo, n_hi)) {
    const double bins = rollspec::spectral::band_bins(dn, b.lower, b.upper);
    if (bins < min_bins) continue;
    const double e = rollspec::spectral::band_average(estimate.data(), estimate.size(), dn, b.lower, b.upper);
    const double t = rollspec::spectral::band_average(target.data(), target.size(), dn, b.lower, b.upper);
    out.push_back({b.centre, bins, db(e / t)});
  }
  return out;
}

// Self-affine with plateau, kink at k_r = 2e3 rad/m and a hard cut-off at k_s = 1e5 rad/m (the jump term of
// Eq. 20), 1 um rms: the line PSD G, and C_iso from it (Eq. 19) at 200 points per decade over [10, 1e9] rad/m.
struct AbelPair {
  rollspec::texture::SelfAffinePsd model{
      rollspec::texture::SelfAffineSpec{0.8, 0.0, 2e3, 1e5, rollspec::texture::RmsTarget::height, 1e-6}};
  rollspec::texture::Psd g = model.to_psd();
  rollspec::texture::IsotropicPsd iso{g, 10.0, 1e9, 200};
};

}  // namespace texture_test
