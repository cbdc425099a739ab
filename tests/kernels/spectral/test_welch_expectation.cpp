// Expected Welch estimate (D-20): FFT kernel against the direct sum, flat spectra stay flat,
// and it predicts the Welch estimate of a long random signal with a narrow resonance.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels/integrators/exact_oscillator_step.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/spectral/welch_expectation.hpp"

using namespace rollspec::spectral;

TEST_CASE("welch_expectation equals its direct evaluation and keeps a flat PSD flat") {
  WelchConfig cfg;
  cfg.sample_rate = 64.0;
  cfg.segment = 32;
  cfg.overlap = 16;
  WelchPlan plan(cfg);
  const std::size_t refine = 4, nfine = refine * (plan.n_freq() - 1) + 1;
  std::vector<double> peak(nfine);
  for (std::size_t j = 0; j < nfine; ++j) {
    const double f = 0.5 * static_cast<double>(j);
    peak[j] = 1.0 / (1.0 + std::pow((f - 10.0) / 0.3, 2));
  }
  const auto fast = welch_expectation(plan, peak, refine), slow = welch_expectation_direct(plan, peak, refine);
  for (std::size_t k = 0; k < fast.size(); ++k) CHECK(fast[k] == doctest::Approx(slow[k]).epsilon(1e-12).scale(1e-12));
  const std::vector<double> flat(nfine, 2.5);
  const auto e = welch_expectation(plan, flat, refine);
  // Away from DC and Nyquist (where the folding counts the window's tail twice) a flat PSD stays flat.
  for (std::size_t k = 3; k + 3 < e.size(); ++k) CHECK(e[k] == doctest::Approx(2.5).epsilon(2e-3));
}

TEST_CASE("Welch estimates of a lightly damped oscillator converge to the expectation, not to S") {
  // White force through q'' + 2 zeta w q' + w^2 q = f; S_q = S_f / |w^2 - W^2 + 2i zeta w W|^2.
  const double fs = 256.0, fn = 20.0, zeta = 0.004, sf = 1.0;
  WelchConfig cfg;
  cfg.sample_rate = fs;
  cfg.segment = 256;  // 1 Hz bins, resonance half-power width 0.16 Hz: unresolved
  cfg.overlap = 128;
  WelchPlan plan(cfg);
  std::mt19937_64 gen(11);
  std::normal_distribution<double> normal(0.0, std::sqrt(sf * fs / 2.0));
  const std::size_t n = 1 << 21;
  const auto step = rollspec::integrators::ExactOscillatorStep::make(2 * M_PI * fn, zeta, 1.0 / fs);
  std::vector<double> q(n);
  double x = 0.0, v = 0.0, f0 = normal(gen);
  for (std::size_t i = 0; i < n; ++i) {
    const double f1 = normal(gen);
    step.advance(x, v, f0, f1);
    q[i] = x;
    f0 = f1;
  }
  std::vector<double> est(plan.n_freq());
  WelchWorkspace ws(cfg.segment);
  plan.psd(q.data() + 65536, n - 65536, est.data(), ws);
  const std::size_t refine = 64, nfine = refine * (plan.n_freq() - 1) + 1;
  std::vector<double> exact(nfine);
  for (std::size_t j = 0; j < nfine; ++j) {
    const double W = 2 * M_PI * (fs / 2.0) * static_cast<double>(j) / static_cast<double>(nfine - 1);
    const double w = 2 * M_PI * fn;
    const double s = W / (fs / 2.0 * 2 * M_PI) * M_PI;  // pi f / fs
    const double hold = j == 0 ? 1.0 : std::pow(std::sin(s) / s, 2);  // first-order hold of the sampled force
    exact[j] = hold * sf / (std::pow(w * w - W * W, 2) + std::pow(2 * zeta * w * W, 2));
  }
  const auto expected = welch_expectation(plan, exact, refine);
  // At the resonance bin the raw S overstates the estimate many times over; the expectation holds.
  const std::size_t k = 20;
  CHECK(exact[k * refine] / est[k] > 3.0);
  // ~16000 segments: 1.2 % standard error per bin.
  for (std::size_t kk = 12; kk <= 28; ++kk) CHECK(est[kk] == doctest::Approx(expected[kk]).epsilon(0.05));
}
