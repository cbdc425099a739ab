// Line textures (D-3): exact periodograms with deterministic amplitudes, Rayleigh ensembles,
// rms against the target's integral, the sampling check, and the time view (D-2).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <random>
#include <string>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/statistics.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "kernels/texture/time_signal.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
constexpr double kDx = 1e-4;  // 0.1 mm
constexpr std::size_t kN = 4096;

// H = 0.8, 1 um rms, plateau from k_l = dk/2 (so harmonic j covers [(j-1/2) dk, (j+1/2) dk]),
// roll-off at 40 dk, cut off at the Nyquist wavenumber pi/dx.
SelfAffinePsd test_psd(std::size_t n) {
  const double dk = 2.0 * M_PI / (static_cast<double>(n) * kDx);
  return SelfAffinePsd(SelfAffineSpec{0.8, 0.5 * dk, 40.0 * dk, M_PI / kDx, RmsTarget::height, 1e-6});
}
}  // namespace

TEST_CASE("deterministic amplitudes: the periodogram of one realisation equals the target at every harmonic") {
  const Psd psd = test_psd(kN).to_psd();
  const LineTextureGenerator gen(psd, LineTextureSpec{kN, kDx, 0, Amplitudes::deterministic, false});
  REQUIRE(gen.period() == kN);
  std::mt19937_64 rng(11);
  const auto h = gen.generate(uniforms(rng, gen.harmonics()), {});
  const auto p = texture_test::periodogram(h, kDx);
  const auto& g = gen.target_psd();
  double worst = 0.0;
  for (std::size_t j = 1; j + 1 < g.size(); ++j) worst = std::max(worst, std::abs(p[j] / g[j] - 1.0));
  MESSAGE("max relative periodogram error over " << g.size() - 2 << " harmonics: " << worst);
  CHECK(worst <= 1e-10);
}

TEST_CASE("the FFT line texture equals the plain cosine sum (reference oracle)") {
  const std::size_t n = 512;
  const Psd psd = test_psd(n).to_psd();
  const LineTextureGenerator gen(psd, LineTextureSpec{n, kDx, 0, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(5);
  const auto up = uniforms(rng, gen.harmonics()), ua = uniforms(rng, gen.harmonics());
  const auto fast = gen.generate(up, ua);
  const auto slow =
      rollspec::spectral::synthesise_direct(gen.target_psd(), gen.fundamental(), Amplitudes::rayleigh, up, ua, n);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    worst = std::max(worst, std::abs(fast[i] - slow[i]));
    scale = std::max(scale, std::abs(slow[i]));
  }
  CHECK(worst <= 1e-12 * scale);
}

TEST_CASE("deterministic amplitudes: rms height within 0.1 % of sqrt(integral of G)") {
  const std::size_t n = 1 << 14;
  const SelfAffinePsd model = test_psd(n);
  const LineTextureGenerator gen(model.to_psd(), LineTextureSpec{n, kDx, 0, Amplitudes::deterministic, false});
  std::mt19937_64 rng(3);
  const auto h = gen.generate(uniforms(rng, gen.harmonics()), {});
  const HeightStatistics st = line_statistics(h.data(), h.size(), kDx);
  const double target = model.rms_height();  // sqrt of the exact integral, Eq. 7
  MESSAGE("rms " << st.rms << " m, target " << target << " m, relative error " << st.rms / target - 1.0);
  CHECK(std::abs(st.rms / target - 1.0) <= 1e-3);
}

TEST_CASE(
    "Rayleigh amplitudes: the mean periodogram of 200 realisations is within 0.5 dB in every band of >= 10 harmonics") {
  const Psd psd = test_psd(kN).to_psd();
  const LineTextureGenerator gen(psd, LineTextureSpec{kN, kDx, 0, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(2024);
  std::vector<double> mean(gen.harmonics(), 0.0);
  const int count = 200;
  for (int r = 0; r < count; ++r) {
    const auto up = uniforms(rng, gen.harmonics()), ua = uniforms(rng, gen.harmonics());
    const auto p = texture_test::periodogram(gen.generate(up, ua), kDx);
    for (std::size_t j = 0; j < mean.size(); ++j) mean[j] += p[j] / count;
  }
  const double dn = spatial_frequency_from_wavenumber(gen.fundamental());
  const auto bands = texture_test::compare_bands(mean, gen.target_psd(), dn, dn, 0.5 / kDx, 10.0);
  REQUIRE(bands.size() >= 8);
  double worst = 0.0;
  for (const auto& b : bands) {
    worst = std::max(worst, std::abs(b.delta_db));
    CHECK(std::abs(b.delta_db) <= 0.5);
  }
  MESSAGE(bands.size() << " bands from " << bands.front().centre_n << " to " << bands.back().centre_n
                       << " cycles/m, worst |dL| = " << worst << " dB");
}

TEST_CASE("any length: a texture shorter than its period is the period's first samples") {
  const Psd psd = test_psd(kN).to_psd();
  const LineTextureGenerator gen(psd, LineTextureSpec{1001, kDx, 0, Amplitudes::rayleigh, false});
  CHECK(gen.period() == 1008);  // 2^4 3^2 7, the smallest fast even length >= 1001
  const LineTextureGenerator full(psd, LineTextureSpec{1008, kDx, 1008, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(8);
  const auto up = uniforms(rng, gen.harmonics()), ua = uniforms(rng, gen.harmonics());
  const auto a = gen.generate(up, ua), b = full.generate(up, ua);
  REQUIRE(a.size() == 1001);
  CHECK(std::equal(a.begin(), a.end(), b.begin()));
}

TEST_CASE("sampling check: dx > pi / k_max is refused unless truncation is allowed") {
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 100.0, 1e5, RmsTarget::height, 1e-6});
  CHECK_THROWS_WITH_AS(
      LineTextureGenerator(model.to_psd(), LineTextureSpec{1024, 1e-4, 0, Amplitudes::rayleigh, false}),
      doctest::Contains("a finer dx or a PSD that ends at or below pi/dx"), UnresolvedPsd);
  try {  // k_max rides along, so a caller can say how fine the grid must be
    LineTextureGenerator(model.to_psd(), LineTextureSpec{1024, 1e-4, 0, Amplitudes::rayleigh, false});
  } catch (const UnresolvedPsd& e) {
    CHECK(e.k_max == 1e5);
    CHECK(std::string(e.what()).find("truncation") == std::string::npos);
  }
  CHECK_NOTHROW(LineTextureGenerator(model.to_psd(), LineTextureSpec{1024, 1e-4, 0, Amplitudes::rayleigh, true}));
  CHECK_NOTHROW(
      LineTextureGenerator(model.to_psd(), LineTextureSpec{1024, M_PI / 1e5, 0, Amplitudes::rayleigh, false}));
  // A table without extension that does not reach down to the fundamental is an error, named.
  const TabulatedPsd t({100.0, 1e4}, {1e-12, 1e-16});
  CHECK_THROWS_WITH_AS(
      LineTextureGenerator(t.to_psd(), LineTextureSpec{1024, M_PI / 1e4, 0, Amplitudes::rayleigh, false}),
      doctest::Contains("no extension"), std::domain_error);
}

TEST_CASE("time view at speed v (D-2): dt = dx / v and G_t(f) integrates to the same variance") {
  const SelfAffinePsd model = test_psd(kN);
  const Psd psd = model.to_psd();
  const double v = 3.0;
  const TimeSignal ts = line_to_time_signal(std::vector<double>(16, 1.0), kDx, v);
  CHECK(ts.dt == doctest::Approx(kDx / v));
  const auto gt = time_psd(psd, v);
  // sum over f of G_t df with df = v dk / 2 pi equals sum over k of G dk.
  const double dk = 2.0 * M_PI / (static_cast<double>(kN) * kDx), df = v * dk / (2.0 * M_PI);
  double var_t = 0.0, var_k = 0.0;
  for (std::size_t j = 1; j < kN / 2; ++j) {
    var_t += gt(df * static_cast<double>(j)) * df;
    var_k += psd(dk * static_cast<double>(j)) * dk;
  }
  CHECK(var_t == doctest::Approx(var_k).epsilon(1e-12));
  CHECK_THROWS_AS(time_psd(psd, 0.0), std::invalid_argument);
}
