// Expected Welch estimate (D-20): FFT kernel against the direct sum, flat spectra stay flat,
// and it predicts the Welch estimate of a long random signal with a narrow resonance.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "kernels/integrators/exact_oscillator_step.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/spectral/welch_expectation.hpp"
#include "welch_config.hpp"

using namespace rollspec::spectral;
using rollspec::spectral::testing::welch_config;

TEST_CASE("welch_expectation equals its direct evaluation and keeps a flat PSD flat") {
  const WelchPlan plan(welch_config(64.0, 32, 16));
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
  const WelchConfig cfg = welch_config(fs, 256, 128);  // 1 Hz bins, resonance half-power width 0.16 Hz: unresolved
  const WelchPlan plan(cfg);
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
    const double s = W / (fs / 2.0 * 2 * M_PI) * M_PI;                // pi f / fs
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

TEST_CASE("welch_expectation beyond f_s/2 is the expectation with aliasing (the folded PSD)") {
  const WelchPlan plan(welch_config(64.0, 32, 16));
  const std::size_t refine = 4, half = refine * (plan.n_freq() - 1);
  std::vector<double> wide(3 * half + 1), folded(half + 1, 0.0);
  for (std::size_t j = 0; j < wide.size(); ++j) {
    const double f = 0.25 * static_cast<double>(j);
    wide[j] = 1.0 / (1.0 + std::pow((f - 40.0) / 0.7, 2)) + 0.2 / (1.0 + f / 20.0);  // a peak above f_s/2 = 32 Hz
  }
  // The one-sided PSD of the sampled signal: S(f) + S(f_s - f) + S(f_s + f) on [0, f_s/2] (the
  // trapezoid nodes and weights of the two integrals coincide).
  for (std::size_t j = 0; j <= half; ++j) folded[j] = wide[j] + wide[2 * half - j] + wide[2 * half + j];
  const auto a = welch_expectation(plan, wide, refine), b = welch_expectation(plan, folded, refine);
  const auto c = welch_expectation_direct(plan, wide, refine);
  const auto narrow = welch_expectation(plan, std::vector<double>(wide.begin(), wide.begin() + half + 1), refine);
  for (std::size_t k = 1; k + 1 < a.size(); ++k) {
    CHECK(a[k] == doctest::Approx(c[k]).epsilon(1e-12));
    CHECK(a[k] == doctest::Approx(b[k]).epsilon(1e-12));
  }
  // The aliased peak (40 Hz -> 24 Hz) is there; without the wide grid it is not.
  CHECK(a[24 * 32 / 64] > 2.0 * narrow[24 * 32 / 64]);
}

TEST_CASE("Welch time weights sum to 1 and taper at the ends; block dof reduces to D-16") {
  const WelchPlan plan(welch_config(100.0, 64, 32));
  const std::size_t n = 64 * 40 + 17;  // 17 samples after the last segment
  const auto tw = welch_time_weights(plan, n);
  double sum = 0.0;
  for (double v : tw) sum += v;
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(tw[0] == 0.0);
  CHECK(tw[n - 1] == 0.0);
  CHECK(tw[n / 2] == doctest::Approx(1.0 / static_cast<double>(plan.segments(n) * 32)).epsilon(1e-9));
  // Blocks of 50 samples; stationary single channel: the D-16 value.
  std::vector<std::size_t> edges;
  for (std::size_t e = 0; e < n; e += 50) edges.push_back(e);
  edges.push_back(n);
  const std::size_t blocks = edges.size() - 1, bins = 3;
  std::vector<std::complex<double>> one(blocks * bins, 2.0);
  const auto d1 = welch_block_dof(plan, n, edges, 1, bins, one);
  for (double v : d1) CHECK(v == doctest::Approx(plan.equivalent_dof(n)).epsilon(1e-9));
  // Three uncorrelated channels of equal level: three times; three identical channels: once.
  std::vector<std::complex<double>> unc(blocks * 6 * bins, 0.0), same(blocks * 6 * bins, 2.0);
  for (std::size_t p = 0; p < blocks; ++p)
    for (std::size_t q : {0u, 3u, 5u})
      for (std::size_t k = 0; k < bins; ++k) unc[(p * 6 + q) * bins + k] = 2.0;
  const auto d3 = welch_block_dof(plan, n, edges, 3, bins, unc), ds = welch_block_dof(plan, n, edges, 3, bins, same);
  for (std::size_t k = 0; k < bins; ++k) {
    CHECK(d3[k] == doctest::Approx(3.0 * plan.equivalent_dof(n)).epsilon(1e-9));
    CHECK(ds[k] == doctest::Approx(plan.equivalent_dof(n)).epsilon(1e-9));
  }
  // A level that rises and falls like sin^2 over the record keeps (E S)^2 / E S^2 = 2/3 of it.
  std::vector<std::complex<double>> wave(blocks * bins);
  for (std::size_t p = 0; p < blocks; ++p)
    for (std::size_t k = 0; k < bins; ++k)
      wave[p * bins + k] = std::pow(
          std::sin(M_PI * 3.0 * static_cast<double>(edges[p] + edges[p + 1]) / 2.0 / static_cast<double>(n)), 2);
  const auto dw = welch_block_dof(plan, n, edges, 1, bins, wave);
  CHECK(dw[0] / plan.equivalent_dof(n) == doctest::Approx(2.0 / 3.0).epsilon(0.03));
}

TEST_CASE("welch_expectation by FFT holds a 1e12 dynamic range and any segment length, aliasing included") {
  // A resonance 1e12 above a steep floor, a segment that is no power of two, S beyond f_s/2: the
  // FFT product must match the term-by-term integral where the expectation is small, too.
  const WelchPlan plan(welch_config(60.0, 30, 15));
  const std::size_t refine = 6, half = refine * (plan.n_freq() - 1);
  std::vector<double> s(4 * half + 1);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double f = 30.0 * static_cast<double>(j) / static_cast<double>(half);
    s[j] = 1e12 / (1.0 + std::pow((f - 11.0) / 0.05, 2)) + std::pow(1.0 + f, -4.0);
  }
  const auto fast = welch_expectation(plan, s, refine), slow = welch_expectation_direct(plan, s, refine);
  double top = 0.0;
  for (double v : slow) top = std::max(top, v);
  for (std::size_t k = 0; k < fast.size(); ++k) CHECK(std::abs(fast[k] - slow[k]) <= 1e-9 * slow[k] + 1e-15 * top);
}
