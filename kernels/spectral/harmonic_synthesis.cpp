#include "kernels/spectral/harmonic_synthesis.hpp"

#include <fftw3.h>

#include <cmath>
#include <stdexcept>

namespace rollspec::spectral {

namespace {
double amplitude(double g, double fundamental, Amplitudes mode, double u_amp) {
  if (g < 0.0 || !std::isfinite(g)) throw std::invalid_argument("PSD values must be finite and non-negative");
  const double a = std::sqrt(2.0 * g * fundamental);
  if (mode == Amplitudes::deterministic) return a;
  // u in (0,1]; u = 0 would give infinity, Philox doubles are strictly positive by construction.
  return a * std::sqrt(-std::log(u_amp));
}
}  // namespace

HarmonicSynthesiser::HarmonicSynthesiser(std::size_t n_samples) : n_(n_samples) {
  if (n_ < 4 || n_ % 2 != 0) throw std::invalid_argument("synthesis length must be even and at least 4");
  const RealBuffer out(n_);
  const ComplexBuffer in(n_ / 2 + 1);
  plan_ = FftwPlan([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n_), in.data(), out.data(), FFTW_ESTIMATE); },
                   "harmonic synthesis (c2r)");
}

void HarmonicSynthesiser::synthesise(const double* psd, double fundamental, Amplitudes mode, const double* u_phase,
                                     const double* u_amplitude, double* out) const {
  const std::size_t nh = harmonics();
  // Buffers owned for the call, so a PSD refused by amplitude() leaks nothing.
  const ComplexBuffer spec(nh);
  const RealBuffer buf(n_);
  spec[0][0] = spec[0][1] = 0.0;
  spec[nh - 1][0] = spec[nh - 1][1] = 0.0;
  // FFTW's c2r computes x_i = X_0 + 2 Re sum_j X_j e^{2 pi i j i/N} + X_{N/2}(-1)^i, so X_j = A_j/2 e^{i phi_j}.
  for (std::size_t j = 1; j + 1 < nh; ++j) {
    const double a = 0.5 * amplitude(psd[j], fundamental, mode, mode == Amplitudes::rayleigh ? u_amplitude[j] : 1.0);
    const double phi = 2.0 * M_PI * u_phase[j];
    spec[j][0] = a * std::cos(phi);
    spec[j][1] = a * std::sin(phi);
  }
  fftw_execute_dft_c2r(plan_.get(), spec.data(), buf.data());
  for (std::size_t i = 0; i < n_; ++i) out[i] = buf[i];
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
      out[i] += a * std::cos(2.0 * M_PI * static_cast<double>(j * i % n_samples) / static_cast<double>(n_samples) + phi);
  }
  return out;
}

}  // namespace rollspec::spectral
