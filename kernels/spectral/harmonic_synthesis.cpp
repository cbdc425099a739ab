#include "kernels/spectral/harmonic_synthesis.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/spectral/tabulated_math.hpp"
#include "kernels/spectral/tabulated_math_avx512.hpp"

namespace rollspec::spectral {

namespace {
#if defined(ROLLSPEC_HAVE_AVX2_PATH)
// Harmonics [j, end) four at a time with AVX2 lanes (D-24, D-25); returns the first not done.
__attribute__((target("avx2"))) std::size_t fill_avx2(std::size_t j, std::size_t end, const double* half_amplitudes,
                                                      bool rayleigh, const double* u_phase, const double* u_amplitude,
                                                      const TabulatedMath& t, FftwComplex* spec) {
  for (; j + 4 <= end; j += 4) {
    __m256d a = _mm256_loadu_pd(half_amplitudes + j);
    if (rayleigh)
      a = _mm256_mul_pd(
          a, _mm256_sqrt_pd(_mm256_max_pd(neg_log_open(_mm256_loadu_pd(u_amplitude + j), t), _mm256_setzero_pd())));
    __m256d c, s;
    sincos_two_pi(_mm256_loadu_pd(u_phase + j), t, c, s);
    const __m256d re = _mm256_mul_pd(a, c), im = _mm256_mul_pd(a, s);
    const __m256d lo = _mm256_unpacklo_pd(re, im), hi = _mm256_unpackhi_pd(re, im);  // (j, j+2), (j+1, j+3)
    _mm256_storeu_pd(spec[j], _mm256_permute2f128_pd(lo, hi, 0x20));
    _mm256_storeu_pd(spec[j + 2], _mm256_permute2f128_pd(lo, hi, 0x31));
  }
  return j;
}

bool cpu_has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
#endif

double deterministic_amplitude(double g, double fundamental) {
  if (g < 0.0 || !std::isfinite(g)) throw std::invalid_argument("PSD values must be finite and non-negative");
  return std::sqrt(2.0 * g * fundamental);
}

double amplitude(double g, double fundamental, Amplitudes mode, double u_amp) {
  const double a = deterministic_amplitude(g, fundamental);
  if (mode == Amplitudes::deterministic) return a;
  // u in (0,1]; u = 0 would give infinity, Philox doubles are strictly positive by construction.
  return a * std::sqrt(-std::log(u_amp));
}
}  // namespace

std::vector<double> synthesis_half_amplitudes(const double* psd, std::size_t nh, double fundamental) {
  std::vector<double> h(nh, 0.0);
  for (std::size_t j = 1; j + 1 < nh; ++j) h[j] = 0.5 * deterministic_amplitude(psd[j], fundamental);
  return h;
}

HarmonicSynthesiser::HarmonicSynthesiser(std::size_t n_samples) : n_(n_samples) {
  if (n_ < 4 || n_ % 2 != 0) throw std::invalid_argument("synthesis length must be even and at least 4");
  const RealBuffer out(n_);
  const ComplexBuffer in(n_ / 2 + 1);
  plan_ = FftwPlan([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n_), in.data(), out.data(), FFTW_ESTIMATE); },
                   "harmonic synthesis (c2r)");
  tabulated_math();  // built here, not inside a realisation
}

// X_j = (A_j / 2) e^{i phi_j} (FFTW's c2r computes x_i = X_0 + 2 Re sum_j X_j e^{2 pi i j i/N} +
// X_{N/2}(-1)^i), A_j = sqrt(2 G_j dk) sqrt(-ln u_j) (D-3), phi_j = 2 pi v_j; -ln u by D-24,
// cos and sin by D-25, no libm call.
void HarmonicSynthesiser::fill_spectrum(const double* half_amplitudes, Amplitudes mode, const double* u_phase,
                                        const double* u_amplitude, FftwComplex* spec) const {
  const std::size_t nh = harmonics();
  const TabulatedMath& t = tabulated_math();
  spec[0][0] = spec[0][1] = 0.0;
  spec[nh - 1][0] = spec[nh - 1][1] = 0.0;
  const bool rayleigh = mode == Amplitudes::rayleigh;
  std::size_t j = 1;
#if defined(ROLLSPEC_HAVE_AVX2_PATH)
  // Widest lanes first (eight, then four, two, one): every form gives the scalar form's bits.
  if (cpu_has_avx512f()) j = fill_spectrum_avx512(j, nh - 1, half_amplitudes, rayleigh, u_phase, u_amplitude, t, spec);
  if (cpu_has_avx2()) j = fill_avx2(j, nh - 1, half_amplitudes, rayleigh, u_phase, u_amplitude, t, spec);
#endif
#if defined(ROLLSPEC_HAVE_SSE2_PATH)
  // Two harmonics per step; the lanes compute exactly what the scalar tail below does.
  for (; j + 2 < nh; j += 2) {
    __m128d a = _mm_loadu_pd(half_amplitudes + j);
    if (rayleigh)
      a = _mm_mul_pd(a, _mm_sqrt_pd(_mm_max_pd(neg_log_open(_mm_loadu_pd(u_amplitude + j), t), _mm_setzero_pd())));
    __m128d c, s;
    sincos_two_pi(_mm_loadu_pd(u_phase + j), t, c, s);
    const __m128d re = _mm_mul_pd(a, c), im = _mm_mul_pd(a, s);
    _mm_storeu_pd(spec[j], _mm_unpacklo_pd(re, im));
    _mm_storeu_pd(spec[j + 1], _mm_unpackhi_pd(re, im));
  }
#endif
  for (; j + 1 < nh; ++j) {
    double a = half_amplitudes[j];
    if (rayleigh) {
      const double l = neg_log_open(u_amplitude[j], t);
      a *= std::sqrt(l > 0.0 ? l : 0.0);
    }
    double c, s;
    sincos_two_pi(u_phase[j], t, c, s);
    spec[j][0] = a * c;
    spec[j][1] = a * s;
  }
}

void HarmonicSynthesiser::check(const SynthesisScratch& scratch) const {
  if (scratch.real.size() != n_ || scratch.spectrum.size() != harmonics())
    throw std::invalid_argument("synthesis scratch made for another length");
}

void HarmonicSynthesiser::synthesise_into_scratch(const double* half_amplitudes, Amplitudes mode, const double* u_phase,
                                                  const double* u_amplitude, SynthesisScratch& scratch) const {
  check(scratch);
  fill_spectrum(half_amplitudes, mode, u_phase, u_amplitude, scratch.spectrum.data());
  fftw_execute_dft_c2r(plan_.get(), scratch.spectrum.data(), scratch.real.data());
}

void HarmonicSynthesiser::synthesise(const double* half_amplitudes, Amplitudes mode, const double* u_phase,
                                     const double* u_amplitude, double* out, SynthesisScratch& scratch) const {
  check(scratch);
  fill_spectrum(half_amplitudes, mode, u_phase, u_amplitude, scratch.spectrum.data());
  // The plan was made on fftw_malloc buffers; a new array of the same alignment runs the same
  // codelets (the same bits), so `out` is written directly when it qualifies.
  if (fftw_alignment_of(out) == fftw_alignment_of(scratch.real.data())) {
    fftw_execute_dft_c2r(plan_.get(), scratch.spectrum.data(), out);
    return;
  }
  fftw_execute_dft_c2r(plan_.get(), scratch.spectrum.data(), scratch.real.data());
  std::copy(scratch.real.data(), scratch.real.data() + n_, out);
}

void HarmonicSynthesiser::synthesise(const double* psd, double fundamental, Amplitudes mode, const double* u_phase,
                                     const double* u_amplitude, double* out) const {
  const std::vector<double> h = synthesis_half_amplitudes(psd, harmonics(), fundamental);
  SynthesisScratch scratch(n_);
  synthesise(h.data(), mode, u_phase, u_amplitude, out, scratch);
}

std::vector<double> synthesise_direct(const std::vector<double>& psd, double fundamental, Amplitudes mode,
                                      const std::vector<double>& u_phase, const std::vector<double>& u_amplitude,
                                      std::size_t n_samples) {
  std::vector<double> out(n_samples, 0.0);
  const std::size_t nh = n_samples / 2 + 1;
  for (std::size_t j = 1; j + 1 < nh; ++j) {
    const double a = amplitude(psd[j], fundamental, mode, mode == Amplitudes::rayleigh ? u_amplitude[j] : 1.0);
    const double phi = 2.0 * M_PI * u_phase[j];
    for (std::size_t i = 0; i < n_samples; ++i)
      out[i] +=
          a * std::cos(2.0 * M_PI * static_cast<double>(j * i % n_samples) / static_cast<double>(n_samples) + phi);
  }
  return out;
}

}  // namespace rollspec::spectral
