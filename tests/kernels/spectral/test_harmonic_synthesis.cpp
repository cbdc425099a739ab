// Spectral-representation synthesis (D-3): FFT path against the direct cosine sum, exact power.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"

using namespace rollspec::spectral;

TEST_CASE("FFT synthesis equals the direct cosine sum (reference oracle)") {
  const std::size_t n = 256;
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> u(1e-12, 1.0);
  std::vector<double> psd(n / 2 + 1), up(n / 2 + 1), ua(n / 2 + 1);
  for (std::size_t j = 0; j < psd.size(); ++j) {
    psd[j] = 1.0 / (1.0 + static_cast<double>(j * j));
    up[j] = u(gen);
    ua[j] = u(gen);
  }
  for (auto mode : {Amplitudes::deterministic, Amplitudes::rayleigh}) {
    HarmonicSynthesiser s(n);
    std::vector<double> fast(n);
    s.synthesise(psd.data(), 0.25, mode, up.data(), ua.data(), fast.data());
    const auto slow = synthesise_direct(psd, 0.25, mode, up, ua, n);
    double scale = 0.0;
    for (double v : slow) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < n; ++i) CHECK(std::abs(fast[i] - slow[i]) <= 1e-13 * scale);
  }
}

TEST_CASE("deterministic amplitudes: variance = sum G_j dk exactly") {
  const std::size_t n = 1024;
  std::vector<double> psd(n / 2 + 1, 2.0), up(n / 2 + 1, 0.37), ua(n / 2 + 1, 0.5);
  HarmonicSynthesiser s(n);
  std::vector<double> x(n);
  s.synthesise(psd.data(), 0.1, Amplitudes::deterministic, up.data(), ua.data(), x.data());
  double var = 0.0;
  for (double v : x) var += v * v;
  var /= static_cast<double>(n);
  CHECK(var == doctest::Approx(2.0 * 0.1 * static_cast<double>(n / 2 - 1)).epsilon(1e-12));
  psd[5] = -1.0;
  CHECK_THROWS_AS(s.synthesise(psd.data(), 0.1, Amplitudes::deterministic, up.data(), ua.data(), x.data()),
                  std::invalid_argument);
}
