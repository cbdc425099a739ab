// Height statistics: FFT autocorrelation against the direct sum, Gaussian moments, 1/e length.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <random>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "kernels/texture/statistics.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

TEST_CASE("autocorrelation: FFT path equals the direct sum (oracle)") {
  std::mt19937_64 rng(1);
  const auto h = uniforms(rng, 777);
  const auto fast = autocorrelation(h.data(), h.size(), 200), slow = autocorrelation_direct(h.data(), h.size(), 200);
  REQUIRE(fast.size() == 201);
  for (std::size_t t = 0; t < fast.size(); ++t) CHECK(std::abs(fast[t] - slow[t]) <= 1e-12);
}

TEST_CASE("correlation length is the linear-interpolated 1/e crossing") {
  // rho = 1, 0.5, 0.25: 1/e = 0.3679 lies between lags 1 and 2 at 1 + (0.5 - 0.3679) / 0.25.
  CHECK(correlation_length_from_acf({1.0, 0.5, 0.25}, 2.0) ==
        doctest::Approx(2.0 * (1.0 + (0.5 - std::exp(-1.0)) / 0.25)));
  CHECK(std::isnan(correlation_length_from_acf({1.0, 0.9, 0.8}, 1.0)));
}

TEST_CASE("a long Rayleigh texture is Gaussian: skewness ~ 0, kurtosis ~ 3; its 1/e length matches the PSD's") {
  const double dx = 1e-5;
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (50.0 * dx), M_PI / dx, RmsTarget::height, 1e-6});
  const std::size_t n = 1 << 20;
  const LineTextureGenerator gen(model.to_psd(), LineTextureSpec{n, dx, 0, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(12);
  const auto h = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
  const HeightStatistics st = line_statistics(h.data(), h.size(), dx);
  // Expected 1/e length from the target autocovariance R(s) = sum_j G_j dk cos(k_j s dx).
  const auto& g = gen.target_psd();
  std::vector<double> rho(200, 0.0);
  for (std::size_t s = 0; s < rho.size(); ++s)
    for (std::size_t j = 1; j < g.size(); ++j)
      rho[s] += g[j] * std::cos(gen.fundamental() * static_cast<double>(j) * dx * static_cast<double>(s));
  for (std::size_t s = rho.size(); s-- > 0;) rho[s] /= rho[0];
  const double expected = correlation_length_from_acf(rho, dx);
  MESSAGE("rms " << st.rms << " (target " << model.rms_height() << "), skewness " << st.skewness << ", kurtosis "
                 << st.kurtosis << ", correlation length " << st.correlation_length_x << " m (expected " << expected
                 << " m)");
  CHECK(std::abs(st.skewness) < 0.05);
  CHECK(std::abs(st.kurtosis - 3.0) < 0.1);
  CHECK(st.correlation_length_x == doctest::Approx(expected).epsilon(0.05));
  CHECK(st.rms == doctest::Approx(model.rms_height()).epsilon(0.05));
}

TEST_CASE("radially averaged 2D PSD: the bins partition the modes, so (2 pi)^-2 sum_b C_b modes_b dqx dqy = variance") {
  const double d = 1e-6;
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (16.0 * d), M_PI / d, RmsTarget::height, 0.2e-6});
  const SpectralSurfaceGenerator gen(model.to_psd(),
                                     SpectralSurfaceSpec{64, 32, d, 2.0 * d, Amplitudes::rayleigh, 1.0, true, 100});
  std::mt19937_64 rng(4);
  const auto up = uniforms(rng, gen.modes()), ua = uniforms(rng, gen.modes());
  Surface s;
  gen.generate(up.data(), ua.data(), s);
  const RadialPsd r = radially_averaged_psd(s);
  const double dqx = 2.0 * M_PI / (64 * d), dqy = 2.0 * M_PI / (32 * 2.0 * d);
  double var = 0.0, modes = 0.0;
  for (std::size_t b = 0; b < r.psd.size(); ++b) {
    var += r.psd[b] * r.modes[b] * dqx * dqy / (4.0 * M_PI * M_PI);
    modes += r.modes[b];
  }
  const HeightStatistics st = surface_statistics(s);
  CHECK(var == doctest::Approx(st.rms * st.rms).epsilon(1e-10));
  CHECK(modes == doctest::Approx(64.0 * 32.0 - 1.0));  // every mode but DC
  for (std::size_t b = 1; b < r.q.size(); ++b) CHECK(r.q[b] > r.q[b - 1]);
}

TEST_CASE("mean statistics: field-wise mean, NaN correlation lengths skipped") {
  HeightStatistics a, b;
  a.rms = 1.0;
  b.rms = 3.0;
  a.correlation_length_x = 2.0;
  b.correlation_length_x = std::nan("");
  a.correlation_length_y = b.correlation_length_y = std::nan("");
  const HeightStatistics m = mean_statistics({a, b});
  CHECK(m.rms == 2.0);
  CHECK(m.correlation_length_x == 2.0);
  CHECK(std::isnan(m.correlation_length_y));
}

TEST_CASE("spread over realisations: sample standard deviation, NaN fields left out") {
  HeightStatistics a, b, c;
  a.rms = 1.0;
  b.rms = 2.0;
  c.rms = 6.0;  // mean 3, squares 4 + 1 + 9 = 14, / (3 - 1) = 7
  a.correlation_length_x = 1.0;
  b.correlation_length_x = std::nan("");
  c.correlation_length_x = 3.0;  // two finite values: |1 - 3| / sqrt(2)
  a.correlation_length_y = 5.0;
  b.correlation_length_y = c.correlation_length_y = std::nan("");  // one finite value: no spread
  const HeightStatistics d = std_statistics({a, b, c});
  CHECK(d.rms == doctest::Approx(std::sqrt(7.0)).epsilon(1e-15));
  CHECK(d.correlation_length_x == doctest::Approx(std::sqrt(2.0)).epsilon(1e-15));
  CHECK(std::isnan(d.correlation_length_y));
  CHECK(d.skewness == 0.0);
}
