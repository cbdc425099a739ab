// Welch PSD: Parseval, exact sinusoid power, equivalent degrees of freedom.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "kernels/spectral/welch.hpp"

using namespace rollspec::spectral;

namespace {

// Rectangular windows without overlap: the averaged periodogram, whose Parseval sum is exact.
WelchConfig periodogram_config(double sample_rate, std::size_t segment) {
  WelchConfig cfg;
  cfg.sample_rate = sample_rate;
  cfg.segment = segment;
  cfg.overlap = 0;
  cfg.window = Window::rectangular;
  return cfg;
}

std::vector<double> psd_of(const WelchPlan& plan, const std::vector<double>& x) {
  WelchWorkspace ws(plan.config().segment);
  std::vector<double> p(plan.n_freq());
  plan.psd(x.data(), x.size(), p.data(), ws);
  return p;
}

}  // namespace

TEST_CASE("Welch PSD of white noise integrates to its variance (Parseval)") {
  // For a rectangular window without overlap, sum_k P_k df equals the mean of the segments'
  // variances exactly (discrete Parseval); with Hann it holds in expectation for white noise.
  std::mt19937_64 gen(7);
  std::normal_distribution<double> normal(0.0, 2.0);
  const std::size_t n = 1 << 16;
  std::vector<double> x(n);
  for (auto& v : x) v = normal(gen);
  WelchConfig cfg = periodogram_config(1000.0, 1024);
  const WelchPlan plan(cfg);
  std::vector<double> p = psd_of(plan, x);
  double integral = 0.0;
  for (double v : p) integral += v * plan.frequency_step();
  double var_segments = 0.0;
  for (std::size_t s = 0; s < n / 1024; ++s) {
    double mean = 0.0, sq = 0.0;
    for (std::size_t i = 0; i < 1024; ++i) mean += x[s * 1024 + i];
    mean /= 1024.0;
    for (std::size_t i = 0; i < 1024; ++i) sq += (x[s * 1024 + i] - mean) * (x[s * 1024 + i] - mean);
    var_segments += sq / 1024.0;
  }
  var_segments /= static_cast<double>(n / 1024);
  CHECK(integral == doctest::Approx(var_segments).epsilon(1e-12));

  // Hann, 50 % overlap: expectation matches the variance 4; 64 segments give ~2 % scatter.
  cfg.window = Window::hann;
  cfg.overlap = 512;
  const WelchPlan hann(cfg);
  p = psd_of(hann, x);
  integral = 0.0;
  for (double v : p) integral += v * hann.frequency_step();
  CHECK(integral == doctest::Approx(4.0).epsilon(0.03));
}

TEST_CASE("Welch PSD of a bin-centred sinusoid holds its power A^2/2 in one bin (rectangular)") {
  const double fs = 256.0, f0 = 32.0, a = 3.0;
  const std::size_t n = 4096;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = a * std::cos(2.0 * M_PI * f0 * static_cast<double>(i) / fs + 0.3);
  const WelchPlan plan(periodogram_config(fs, 256));
  const std::vector<double> p = psd_of(plan, x);
  const std::size_t k0 = 32;  // f0 / df
  CHECK(p[k0] * plan.frequency_step() == doctest::Approx(a * a / 2.0).epsilon(1e-12));
  double rest = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    if (k != k0) rest += p[k];
  CHECK(rest < 1e-20);
}

TEST_CASE("equivalent degrees of freedom: 2 per segment without overlap, Welch's value with Hann 50 %") {
  WelchConfig cfg;
  cfg.segment = 256;
  cfg.overlap = 0;
  cfg.window = Window::rectangular;
  CHECK(WelchPlan(cfg).equivalent_dof(256 * 10) == doctest::Approx(20.0));
  cfg.window = Window::hann;
  cfg.overlap = 128;
  // Percival & Walden: Hann 50 % overlap has rho(1)^2 = 1/36 * ... ~0.0278; nu -> 2 N_B / (1 + 2 * 0.0278) for large
  // N_B.
  const WelchPlan plan(cfg);
  const std::size_t nb = 1000;
  const double nu = plan.equivalent_dof(128 * (nb + 1));
  CHECK(nu / (2.0 * static_cast<double>(nb)) ==
        doctest::Approx(1.0 / (1.0 + 2.0 * (1.0 / 36.0) * (1.0 - 1.0 / 1000.0))).epsilon(1e-9));
}

TEST_CASE("Welch refuses a signal shorter than one segment and a bad configuration") {
  WelchConfig cfg;
  cfg.segment = 64;
  cfg.overlap = 32;
  WelchPlan plan(cfg);
  WelchWorkspace ws(64);
  std::vector<double> x(10, 1.0), p(plan.n_freq());
  CHECK_THROWS_AS(plan.psd(x.data(), x.size(), p.data(), ws), std::invalid_argument);
  cfg.overlap = 64;
  CHECK_THROWS_AS(WelchPlan{cfg}, std::invalid_argument);
}
