#pragma once
// Spectral-representation synthesis of a stationary random signal from a one-sided PSD
// (Shinozuka & Deodatis 1991; theory D-3), by one inverse real FFT:
//
//   h_i = sum_{j=1}^{N/2-1} A_j cos(2 pi j i / N + phi_j),   i = 0..N-1,
//   deterministic: A_j = sqrt(2 G_j dk)            (every realisation's periodogram = target)
//   Rayleigh:      A_j = sqrt(2 G_j dk) sqrt(-ln u_j) (Gaussian field, E[A_j^2] = 2 G_j dk)
//   phi_j = 2 pi v_j
//
// G_j = G(j dk) is the one-sided PSD at harmonic j of the fundamental dk = 2 pi / (N dx) (or
// df = 1/(N dt) in time). The result has period N samples. DC and Nyquist carry no power.
// Random numbers come in as U(0,1) arrays drawn by the caller (the engine's Philox streams),
// so the kernel itself is deterministic.
//
// Fast path: what does not change between realisations is tabulated once (the half amplitudes
// sqrt(2 G_j dk) / 2, the FFTW plan, the buffers in a SynthesisScratch); per harmonic there is
// no libm call: -ln u and cos/sin of 2 pi v come from tabulated_math.hpp (D-24, D-25), within a
// few ulp of libm's, eight (AVX-512F), four (AVX2) or two (SSE2) harmonics a step, same bits.
#include <cstddef>
#include <vector>

#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::spectral {

enum class Amplitudes { deterministic, rayleigh };

// sqrt(2 G_j dk) / 2 for j = 0..nh-1 (0 at j = 0 and j = nh - 1, which carry no power): the
// deterministic Fourier coefficient magnitudes, made once per PSD. Throws on a negative or
// non-finite PSD value.
std::vector<double> synthesis_half_amplitudes(const double* psd, std::size_t nh, double fundamental);

// Per-thread FFTW buffers of one synthesis length: reused, so a realisation allocates nothing.
class SynthesisScratch {
 public:
  explicit SynthesisScratch(std::size_t n_samples) : spectrum(n_samples / 2 + 1), real(n_samples) {}
  ComplexBuffer spectrum;
  RealBuffer real;
};

class HarmonicSynthesiser {
 public:
  explicit HarmonicSynthesiser(std::size_t n_samples);
  HarmonicSynthesiser(const HarmonicSynthesiser&) = delete;
  HarmonicSynthesiser& operator=(const HarmonicSynthesiser&) = delete;

  std::size_t samples() const { return n_; }
  std::size_t harmonics() const { return n_ / 2 + 1; }  // j = 0..N/2 (0 and N/2 unused)

  // psd[j] = G(j * fundamental) for j = 0..N/2; u_phase and u_amplitude hold N/2+1 U(0,1)
  // numbers each (u_amplitude ignored for deterministic amplitudes; entries 0 and N/2 unused).
  // Writes N samples to out. Thread-safe (buffers are per call).
  void synthesise(const double* psd, double fundamental, Amplitudes mode, const double* u_phase,
                  const double* u_amplitude, double* out) const;

  // The same series from synthesis_half_amplitudes(): N samples to `out`. The inverse FFT writes
  // straight into `out` when it has FFTW's alignment, else into scratch.real (then copied).
  void synthesise(const double* half_amplitudes, Amplitudes mode, const double* u_phase, const double* u_amplitude,
                  double* out, SynthesisScratch& scratch) const;

  // Fills scratch.spectrum and transforms it into scratch.real (out-of-place use: callers that
  // want only the first samples copy them from there).
  void synthesise_into_scratch(const double* half_amplitudes, Amplitudes mode, const double* u_phase,
                               const double* u_amplitude, SynthesisScratch& scratch) const;

 private:
  void fill_spectrum(const double* half_amplitudes, Amplitudes mode, const double* u_phase, const double* u_amplitude,
                     FftwComplex* spec) const;
  void check(const SynthesisScratch& scratch) const;

  std::size_t n_;
  FftwPlan plan_;  // c2r, made once, executed on per-call buffers
};

// Plain O(N * N/2) cosine sum of the same series: the reference oracle for tests.
std::vector<double> synthesise_direct(const std::vector<double>& psd, double fundamental, Amplitudes mode,
                                      const std::vector<double>& u_phase, const std::vector<double>& u_amplitude,
                                      std::size_t n_samples);

}  // namespace rollspec::spectral
