#pragma once
// Line textures h(x_i), x_i = i dx, by spectral representation (kernels/README.md D-3; README Eq. 12):
//
//   h(x) = sum_{j=1}^{P/2-1} A_j cos(k_j x + phi_j),  k_j = j dk,  dk = 2 pi / (P dx),
//   A_j = sqrt(2 G(k_j) dk) [deterministic]  or  sqrt(2 G(k_j) dk) sqrt(-ln u_j) [Rayleigh],
//   phi_j = 2 pi v_j
//
// evaluated by spectral::HarmonicSynthesiser (one inverse FFT of period P samples); the first
// `samples` values are returned, so any length works (P >= samples, P even). Sampling check:
// dx <= pi / k_max, k_max = psd.support_max (the PSD's power above the Nyquist wavenumber pi/dx
// would be dropped), unless truncation is explicitly allowed.
//
// Random numbers come in as two arrays of harmonics() U(0,1) doubles (phase, amplitude); the
// engine draws them from the realisation's Philox stream. No RNG, no I/O in here. The half
// amplitudes sqrt(2 G_j dk) / 2 and the FFTW plan are made once per generator; a caller that
// generates many realisations passes a SynthesisScratch per thread, so none allocates.
#include <cstddef>
#include <memory>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

using spectral::Amplitudes;
using spectral::SynthesisScratch;

struct LineTextureSpec {
  std::size_t samples = 0;  // output length n
  double spacing = 0.0;     // dx, m
  std::size_t period = 0;   // synthesis period P in samples; 0: smallest even 2^a 3^b 5^c 7^d >= samples
  Amplitudes amplitudes = Amplitudes::rayleigh;
  bool allow_truncation = false;  // accept k_max > pi / dx (the PSD above pi/dx is dropped)
};

class LineTextureGenerator {
 public:
  LineTextureGenerator(const Psd& psd, const LineTextureSpec& spec);

  const LineTextureSpec& spec() const { return spec_; }
  std::size_t period() const { return synth_.samples(); }
  std::size_t harmonics() const { return synth_.harmonics(); }  // length of each U(0,1) array (P/2 + 1)
  double fundamental() const { return dk_; }                    // dk, rad/m
  const std::vector<double>& target_psd() const { return g_; }  // G(j dk), j = 0..P/2 (0 and P/2 carry no power)
  std::vector<double> wavenumbers() const;                      // j dk
  double target_variance() const;                               // sum_j G_j dk over the synthesised harmonics

  // out[0..samples): one realisation. u_amplitude is ignored for deterministic amplitudes.
  void generate(const double* u_phase, const double* u_amplitude, double* out) const;
  void generate(const double* u_phase, const double* u_amplitude, double* out, SynthesisScratch& scratch) const;
  SynthesisScratch make_scratch() const { return SynthesisScratch(synth_.samples()); }
  std::vector<double> generate(const std::vector<double>& u_phase, const std::vector<double>& u_amplitude) const;

 private:
  LineTextureSpec spec_;
  spectral::HarmonicSynthesiser synth_;
  double dk_;
  std::vector<double> g_;
  std::vector<double> half_amplitudes_;  // sqrt(2 G_j dk) / 2
};

// Smallest even number >= n whose only prime factors are 2, 3, 5, 7 (fast FFT sizes).
std::size_t fast_even_length(std::size_t n);

}  // namespace rollspec::texture
