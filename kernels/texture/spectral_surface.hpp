#pragma once
// Isotropic (or anisotropic) Gaussian surfaces by 2D Fourier filtering (kernels/README.md D-5; README
// Eq. 26-28). On an nx x ny grid (both even), dqx = 2 pi / (nx dx), dqy = 2 pi / (ny dy):
//
//   z(x, y) = sum_q Z_q e^{i q.x},  Z_{-q} = conj(Z_q),
//   |Z_q| = sqrt(C(q) dqx dqy) / (2 pi)  [deterministic]  or  x sqrt(-ln u_q)  [Rayleigh],
//   arg Z_q = 2 pi v_q                                                          (Eq. 26)
//   so that E[z^2] = (2 pi)^-2 sum_q C(q) dqx dqy (JJP 2017 normalisation, Eq. 25).
//   C(qx, qy) = C_iso( sqrt((a qx)^2 + (qy / a)^2) ),  a = sqrt(anisotropy)            (Eq. 27)
// anisotropy = (correlation length in x) / (correlation length in y); the stretch is area
// preserving, so rms height is unchanged. C_iso comes from the line PSD (isotropic_psd.hpp), a
// mode takes its radial cell mean (Eq. 21, width sqrt(dqx dqy)). DC, the Nyquist row and the
// Nyquist column carry no power (as the line synthesis). Sampling check, unless truncation is
// allowed: k_max / a <= pi / dx and a k_max <= pi / dy, k_max = the PSD's support_max.
// Rayleigh amplitudes with uniform phases make z a Gaussian field.
//
// Random numbers: two arrays of modes() = ny (nx/2 + 1) U(0,1) doubles (phase, amplitude),
// indexed like the half-plane spectrum [iy * (nx/2+1) + ix]; entries of the qx = 0 column with
// iy > ny/2 are unused (they are the conjugates of iy < ny/2).
#include <complex>
#include <cstddef>
#include <memory>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/texture/isotropic_psd.hpp"
#include "kernels/texture/psd.hpp"
#include "kernels/texture/surface.hpp"
#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::texture {

using spectral::Amplitudes;

struct SpectralSurfaceSpec {
  std::size_t nx = 0, ny = 0;  // even, >= 4
  double dx = 0.0, dy = 0.0;   // m
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;
  double anisotropy = 1.0;  // correlation length ratio x / y
  bool allow_truncation = false;
  std::size_t points_per_decade = 100;  // log grid of the inverse Abel transform
};

class SpectralSurfaceGenerator {
 public:
  SpectralSurfaceGenerator(const Psd& psd, const SpectralSurfaceSpec& spec);
  SpectralSurfaceGenerator(const SpectralSurfaceGenerator&) = delete;
  SpectralSurfaceGenerator& operator=(const SpectralSurfaceGenerator&) = delete;

  const SpectralSurfaceSpec& spec() const { return spec_; }
  std::size_t modes() const { return spec_.ny * (spec_.nx / 2 + 1); }  // length of each U(0,1) array
  const std::vector<double>& mode_psd() const { return c_; }           // target C per half-plane mode, m^4
  const IsotropicPsd& isotropic_psd() const { return *iso_; }
  double target_variance() const;  // (2 pi)^-2 sum_q C dqx dqy over all modes

  // One realisation into out (resized). Thread-safe: buffers are per call.
  void generate(const double* u_phase, const double* u_amplitude, Surface& out) const;
  // The half-plane coefficients Z_q of Eq. 26 (Hermitian-consistent qx = 0 column).
  std::vector<std::complex<double>> coefficients(const double* u_phase, const double* u_amplitude) const;

 private:
  SpectralSurfaceSpec spec_;
  std::unique_ptr<IsotropicPsd> iso_;
  std::vector<double> c_;
  std::vector<double> amp_;  // sqrt(dqx dqy) / (2 pi) sqrt(C_q), Eq. 26
  spectral::FftwPlan plan_;  // 2D c2r, executed on per-call buffers (new-array interface)
};

// Reference oracle: the plain double sum of Eq. 26 over all modes, O((nx ny)^2).
Surface spectral_surface_direct(const SpectralSurfaceGenerator& gen, const double* u_phase, const double* u_amplitude);

}  // namespace rollspec::texture
