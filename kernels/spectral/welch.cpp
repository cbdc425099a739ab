#include "kernels/spectral/welch.hpp"

#include <fftw3.h>

#include <cmath>
#include <stdexcept>

namespace rollspec::spectral {

WelchPlan::WelchPlan(const WelchConfig& config) : config_(config) {
  if (config_.segment < 2) throw std::invalid_argument("Welch segment must hold at least 2 samples");
  if (config_.overlap >= config_.segment) throw std::invalid_argument("Welch overlap must be shorter than the segment");
  if (!(config_.sample_rate > 0.0) || !std::isfinite(config_.sample_rate))
    throw std::invalid_argument("Welch sample rate must be positive and finite");
  window_ = make_window(config_.window, config_.segment);
  double s2 = 0.0;
  for (double w : window_) s2 += w * w;
  scale_ = 1.0 / (config_.sample_rate * s2);
  WelchWorkspace probe(config_.segment);
  plan_ = FftwPlan(
      [&] { return fftw_plan_dft_r2c_1d(static_cast<int>(config_.segment), probe.in(), probe.out(), FFTW_ESTIMATE); },
      "Welch (r2c)");
}

std::vector<double> WelchPlan::frequencies() const {
  std::vector<double> f(n_freq());
  const double df = frequency_step();
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = df * static_cast<double>(k);
  return f;
}

std::size_t WelchPlan::segments(std::size_t n) const {
  if (n < config_.segment) return 0;
  return (n - config_.overlap) / (config_.segment - config_.overlap);
}

void WelchPlan::psd(const double* x, std::size_t n, double* out, WelchWorkspace& ws) const {
  const std::size_t L = config_.segment, step = L - config_.overlap, nf = n_freq();
  const std::size_t ns = segments(n);
  if (ns == 0) throw std::invalid_argument("signal shorter than one Welch segment");
  if (ws.segment() != L) throw std::invalid_argument("Welch workspace has the wrong segment length");
  for (std::size_t k = 0; k < nf; ++k) out[k] = 0.0;
  double* in = ws.in();
  FftwComplex* spec = ws.out();
  for (std::size_t s = 0; s < ns; ++s) {
    const double* seg = x + s * step;
    double mean = 0.0;
    if (config_.detrend == Detrend::constant) {
      for (std::size_t i = 0; i < L; ++i) mean += seg[i];
      mean /= static_cast<double>(L);
    }
    for (std::size_t i = 0; i < L; ++i) in[i] = (seg[i] - mean) * window_[i];
    fftw_execute_dft_r2c(plan_.get(), in, spec);
    for (std::size_t k = 0; k < nf; ++k) out[k] += spec[k][0] * spec[k][0] + spec[k][1] * spec[k][1];
  }
  // D-15: density scaling, one-sided doubling except DC and (even L) Nyquist, mean over segments.
  const double base = scale_ / static_cast<double>(ns);
  for (std::size_t k = 0; k < nf; ++k) {
    const bool unpaired = (k == 0) || (L % 2 == 0 && k == nf - 1);
    out[k] *= unpaired ? base : 2.0 * base;
  }
}

double WelchPlan::equivalent_dof(std::size_t n) const {
  const std::size_t nb = segments(n);
  if (nb == 0) return 0.0;
  const std::size_t L = config_.segment, step = L - config_.overlap;
  double s2 = 0.0;
  for (double w : window_) s2 += w * w;
  double denom = 1.0;
  for (std::size_t m = 1; m < nb && m * step < L; ++m) {
    double r = 0.0;
    for (std::size_t t = 0; t + m * step < L; ++t) r += window_[t] * window_[t + m * step];
    r /= s2;
    denom += 2.0 * (1.0 - static_cast<double>(m) / static_cast<double>(nb)) * r * r;
  }
  return 2.0 * static_cast<double>(nb) / denom;
}

}  // namespace rollspec::spectral
