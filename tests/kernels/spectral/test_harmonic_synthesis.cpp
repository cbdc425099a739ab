// Spectral-representation synthesis (D-3): FFT path against the direct cosine sum, exact power.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/tabulated_math_avx512.hpp"

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

TEST_CASE("tabulated path: one scratch for many realisations; aligned and unaligned outputs give the same bits") {
  const std::size_t n = 1000;  // 2^3 5^3: not a power of two
  HarmonicSynthesiser s(n);
  std::vector<double> psd(s.harmonics());
  for (std::size_t j = 0; j < psd.size(); ++j) psd[j] = 1.0 / (1.0 + 0.01 * static_cast<double>(j * j));
  const std::vector<double> h = synthesis_half_amplitudes(psd.data(), psd.size(), 0.5);
  CHECK(h.front() == 0.0);
  CHECK(h.back() == 0.0);
  CHECK(h[3] == 0.5 * std::sqrt(2.0 * psd[3] * 0.5));
  SynthesisScratch scratch(n);
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(1e-300, 1.0);
  for (int r = 0; r < 3; ++r) {
    std::vector<double> up(s.harmonics()), ua(s.harmonics());
    for (std::size_t j = 0; j < up.size(); ++j) up[j] = u(gen), ua[j] = u(gen);
    const RealBuffer aligned(n);
    std::vector<double> shifted(n + 1), fresh(n);
    s.synthesise(h.data(), Amplitudes::rayleigh, up.data(), ua.data(), aligned.data(), scratch);
    s.synthesise(h.data(), Amplitudes::rayleigh, up.data(), ua.data(), shifted.data() + 1, scratch);
    s.synthesise(psd.data(), 0.5, Amplitudes::rayleigh, up.data(), ua.data(), fresh.data());  // own scratch
    const auto slow = synthesise_direct(psd, 0.5, Amplitudes::rayleigh, up, ua, n);
    double scale = 0.0;
    for (double v : slow) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < n; ++i) {
      CHECK(aligned[i] == shifted[i + 1]);
      CHECK(aligned[i] == fresh[i]);
      CHECK(std::abs(aligned[i] - slow[i]) <= 1e-13 * scale);
    }
  }
  SynthesisScratch wrong(n + 2);
  std::vector<double> up(s.harmonics(), 0.5), ua(s.harmonics(), 0.5), x(n);
  CHECK_THROWS_AS(s.synthesise(h.data(), Amplitudes::rayleigh, up.data(), ua.data(), x.data(), wrong),
                  std::invalid_argument);
}

namespace {
// One harmonic as the scalar fill writes it (kernels/spectral harmonic_synthesis.cpp): the form the
// vector fills must match bit for bit.
std::array<double, 2> scalar_harmonic(double h, bool rayleigh, double up, double ua,
                                      const rollspec::spectral::TabulatedMath& t) {
  double a = h;
  if (rayleigh) {
    const double l = rollspec::spectral::neg_log_open(ua, t);
    a *= std::sqrt(l > 0.0 ? l : 0.0);
  }
  double c, s;
  rollspec::spectral::sincos_two_pi(up, t, c, s);
  return {a * c, a * s};
}

// The eight-lane fill of harmonics first .. h.size() - 2 of (h, up, ua), the buffer preset to -1: where it stopped
// (after its last full step of eight), and the harmonics it wrote that `differ` from the scalar form's.
struct EightLaneFill {
  rollspec::spectral::ComplexBuffer spec;
  std::size_t done = 0, mismatches = 0;
  template <class Differ>
  EightLaneFill(std::size_t first, const std::vector<double>& h, bool rayleigh, const std::vector<double>& up,
                const std::vector<double>& ua, Differ&& differ)
      : spec(h.size()) {
    const rollspec::spectral::TabulatedMath& t = rollspec::spectral::tabulated_math();
    for (std::size_t j = 0; j < h.size(); ++j) spec[j][0] = spec[j][1] = -1.0;
    done = rollspec::spectral::fill_spectrum_avx512(first, h.size() - 1, h.data(), rayleigh, up.data(), ua.data(), t,
                                                    spec.data());
    for (std::size_t j = first; j < done; ++j)
      mismatches += differ(spec[j], scalar_harmonic(h[j], rayleigh, up[j], ua[j], t));
  }
};
}  // namespace

TEST_CASE("the eight-lane (AVX-512F) spectrum fill gives the scalar form's bits") {
  using namespace rollspec::spectral;
  if (!cpu_has_avx512f()) {
    MESSAGE("no AVX-512F on this CPU: eight-lane fill not checked");
    return;
  }
  const std::size_t nh = 1001;
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(1e-300, 1.0);
  std::vector<double> h(nh), up(nh), ua(nh);
  for (std::size_t j = 0; j < nh; ++j) h[j] = u(gen), up[j] = u(gen), ua[j] = u(gen);
  for (bool rayleigh : {true, false}) {
    const EightLaneFill f(3, h, rayleigh, up, ua, [](const FftwComplex& got, const std::array<double, 2>& want) {
      return std::size_t{got[0] != want[0]} + std::size_t{got[1] != want[1]};
    });
    CHECK(f.done == 3 + (nh - 1 - 3) / 8 * 8);
    CHECK(f.mismatches == 0);
    CHECK(f.spec[f.done][0] == -1.0);  // nothing written past the last full step
  }
}

TEST_CASE("the eight-lane fill gives the scalar form's bits at phase ties, log-bin edges and u -> 1") {
  // The fill takes 16 harmonics a step (two interleaved groups), then eight; k = trunc(1024 v + 1/2)
  // comes from a fused multiply-add and a round-down add, e + 1 ln2_hi + ln(c/2) from a fused
  // multiply-add: exact steps, so every bit (signs of zero included) must equal the scalar form's.
  using namespace rollspec::spectral;
  if (!cpu_has_avx512f()) {
    MESSAGE("no AVX-512F on this CPU: eight-lane fill not checked");
    return;
  }
  std::vector<double> up, ua;
  for (int k = 0; k <= 1024; ++k) {
    const double tie = (k + 0.5) / 1024.0, step = k / 1024.0;  // 1024 v + 1/2 an integer; a table point
    for (double v : {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 2.0), step, std::nextafter(step, 2.0)})
      if (v <= 1.0) up.push_back(v);
  }
  up.push_back(0.0);
  up.push_back(5e-324);
  for (int i = 0; i < 256; ++i)
    for (int e : {-1, -2, -40, -1000}) {
      const double edge = std::ldexp(1.0 + i / 256.0, e);
      for (double u : {edge, std::nextafter(edge, 0.0), std::nextafter(edge, 1.0)})
        if (u < 1.0) ua.push_back(u);
    }
  for (int i = 1; i < 64; ++i) ua.push_back(1.0 - i * 0x1p-53);
  const std::size_t nh = std::max(up.size(), ua.size()) + 2;
  std::vector<double> h(nh);
  std::mt19937_64 gen(19);
  std::uniform_real_distribution<double> unit(1e-300, 1.0);
  for (std::size_t j = 0; j < nh; ++j) h[j] = unit(gen);
  up.resize(nh, 0.25);
  ua.resize(nh, 0.5);
  std::shuffle(ua.begin(), ua.end(), gen);  // every phase meets many amplitudes
  for (bool rayleigh : {true, false}) {
    const EightLaneFill f(1, h, rayleigh, up, ua, [](const FftwComplex& got, const std::array<double, 2>& want) {
      return std::size_t{std::memcmp(got, want.data(), sizeof(double) * 2) != 0};
    });
    CHECK(f.done == 1 + (nh - 2) / 8 * 8);
    CHECK(f.mismatches == 0);
  }
}
