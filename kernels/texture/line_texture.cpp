#include "kernels/texture/line_texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

namespace {
std::size_t resolve_period(const LineTextureSpec& s) {
  if (s.samples < 2) throw std::invalid_argument("line texture needs at least 2 samples");
  if (!(s.spacing > 0.0) || !std::isfinite(s.spacing))
    throw std::invalid_argument("line texture spacing dx must be positive and finite");
  if (s.period == 0) return fast_even_length(std::max<std::size_t>(s.samples, 4));
  if (s.period < s.samples || s.period % 2 != 0 || s.period < 4)
    throw std::invalid_argument("line texture period " + std::to_string(s.period) +
                                " must be even, >= 4 and >= samples (" + std::to_string(s.samples) + ")");
  return s.period;
}

std::string g6(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void check_sampling(const Psd& psd, double dx, bool allow_truncation) {
  const double k_nyquist = M_PI / dx;
  if (psd.support_max > k_nyquist * (1.0 + 1e-12) && !allow_truncation)
    throw UnresolvedPsd("sampling dx = " + g6(dx) + " m resolves k up to pi/dx = " + g6(k_nyquist) +
                            " rad/m, but the PSD (" + psd.description + ") carries power up to k_max = " +
                            g6(psd.support_max) + " rad/m; a finer dx or a PSD that ends at or below pi/dx resolves it",
                        psd.support_max);
}
}  // namespace

std::size_t fast_even_length(std::size_t n) {
  for (std::size_t m = n + (n % 2);; m += 2) {
    std::size_t r = m;
    for (std::size_t p : {2u, 3u, 5u, 7u})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

LineTextureGenerator::LineTextureGenerator(const Psd& psd, const LineTextureSpec& spec)
    : spec_(spec), synth_(resolve_period(spec)), dk_(0.0) {
  check_sampling(psd, spec.spacing, spec.allow_truncation);
  spec_.period = synth_.samples();
  dk_ = 2.0 * M_PI / (static_cast<double>(synth_.samples()) * spec.spacing);
  g_ = psd_at_harmonics(psd, dk_, synth_.harmonics());
  g_.back() = 0.0;  // Nyquist harmonic carries no power (D-3 sum stops at P/2 - 1)
  half_amplitudes_ = spectral::synthesis_half_amplitudes(g_.data(), g_.size(), dk_);
}

std::vector<double> LineTextureGenerator::wavenumbers() const {
  std::vector<double> k(g_.size());
  for (std::size_t j = 0; j < k.size(); ++j) k[j] = dk_ * static_cast<double>(j);
  return k;
}

double LineTextureGenerator::target_variance() const {
  double v = 0.0;
  for (std::size_t j = 1; j + 1 < g_.size(); ++j) v += g_[j] * dk_;
  return v;
}

void LineTextureGenerator::generate(const double* u_phase, const double* u_amplitude, double* out,
                                    SynthesisScratch& scratch) const {
  if (spec_.samples == synth_.samples()) {
    synth_.synthesise(half_amplitudes_.data(), spec_.amplitudes, u_phase, u_amplitude, out, scratch);
    return;
  }
  synth_.synthesise_into_scratch(half_amplitudes_.data(), spec_.amplitudes, u_phase, u_amplitude, scratch);
  std::copy(scratch.real.data(), scratch.real.data() + spec_.samples, out);
}

void LineTextureGenerator::generate(const double* u_phase, const double* u_amplitude, double* out) const {
  SynthesisScratch scratch = make_scratch();
  generate(u_phase, u_amplitude, out, scratch);
}

std::vector<double> LineTextureGenerator::generate(const std::vector<double>& u_phase,
                                                   const std::vector<double>& u_amplitude) const {
  if (u_phase.size() < harmonics() || (spec_.amplitudes == Amplitudes::rayleigh && u_amplitude.size() < harmonics()))
    throw std::invalid_argument("line texture needs " + std::to_string(harmonics()) + " U(0,1) numbers per array");
  std::vector<double> out(spec_.samples);
  generate(u_phase.data(), u_amplitude.empty() ? nullptr : u_amplitude.data(), out.data());
  return out;
}

}  // namespace rollspec::texture
