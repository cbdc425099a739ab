// 2D Fourier-filtered surfaces (D-5): oracle, exact mode powers, ensemble radial PSD against
// C_iso, line profiles against the line PSD, anisotropy.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <random>

#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "kernels/texture/statistics.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
constexpr double kD = 1e-6;  // 1 um grid
// H = 0.8, roll-off at a wavelength of 32 cells, 0.2 um rms, cut off at pi / dx.
SelfAffinePsd surface_psd() {
  return SelfAffinePsd(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (32.0 * kD), M_PI / kD, RmsTarget::height, 0.2e-6});
}
}  // namespace

TEST_CASE("spectral surface: FFT path equals the plain double sum (reference oracle)") {
  const SpectralSurfaceGenerator gen(surface_psd().to_psd(),
                                     SpectralSurfaceSpec{16, 12, kD, kD, Amplitudes::rayleigh, 1.0, false, 100});
  std::mt19937_64 rng(1);
  const auto up = uniforms(rng, gen.modes()), ua = uniforms(rng, gen.modes());
  Surface fast;
  gen.generate(up.data(), ua.data(), fast);
  const Surface slow = spectral_surface_direct(gen, up.data(), ua.data());
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < fast.heights.size(); ++i) {
    worst = std::max(worst, std::abs(fast.heights[i] - slow.heights[i]));
    scale = std::max(scale, std::abs(slow.heights[i]));
  }
  CHECK(worst <= 1e-12 * scale);
}

TEST_CASE("spectral surface, deterministic amplitudes: periodogram = target C at every mode; variance = target") {
  const SpectralSurfaceGenerator gen(surface_psd().to_psd(),
                                     SpectralSurfaceSpec{64, 48, kD, kD, Amplitudes::deterministic, 1.0, false, 100});
  std::mt19937_64 rng(2);
  const auto up = uniforms(rng, gen.modes());
  Surface s;
  gen.generate(up.data(), nullptr, s);
  const auto c = surface_periodogram(s);
  double worst = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (gen.mode_psd()[i] > 0.0) worst = std::max(worst, std::abs(c[i] / gen.mode_psd()[i] - 1.0));
  CHECK(worst <= 1e-10);
  const HeightStatistics st = surface_statistics(s);
  CHECK(st.rms * st.rms == doctest::Approx(gen.target_variance()).epsilon(1e-10));
}

TEST_CASE("a narrow strip holds the variance of a square surface (Eq. 26a)") {
  // 1024 x 8 cells against 1024 x 1024: the strip's modes of the rows q_y = 0, ±Δq_y stand for cells
  // 128 times longer in q_y than in q_x, across the roll-off plateau (k_r = 2π/32 cells; Δq_y = 4 k_r).
  // Both sums (Eq. 28) approximate (2π)⁻² ∫ C d²q without the same DC cell; one radial mean per
  // mode (Eq. 21 alone) gave the strip 1.31x the variance.
  const Psd psd = surface_psd().to_psd();
  const SpectralSurfaceGenerator square(
      psd, SpectralSurfaceSpec{1024, 1024, kD, kD, Amplitudes::deterministic, 1.0, false, 100});
  const SpectralSurfaceGenerator strip(
      psd, SpectralSurfaceSpec{1024, 8, kD, kD, Amplitudes::deterministic, 1.0, false, 100});
  MESSAGE("strip / square variance = " << strip.target_variance() / square.target_variance());
  CHECK(strip.target_variance() / square.target_variance() == doctest::Approx(1.0).epsilon(0.03));
}

TEST_CASE(
    "spectral surfaces: 50 Rayleigh surfaces match C_iso within 0.5 dB per band; their rows match G within 1 dB") {
  const std::size_t n = 256;
  const SelfAffinePsd model = surface_psd();
  const SpectralSurfaceGenerator gen(model.to_psd(),
                                     SpectralSurfaceSpec{n, n, kD, kD, Amplitudes::rayleigh, 1.0, false, 100});
  const std::size_t nh = n / 2 + 1;
  const double dq = 2.0 * M_PI / (static_cast<double>(n) * kD);
  std::mt19937_64 rng(50);
  std::vector<double> mean_c(gen.modes(), 0.0), mean_row(nh, 0.0);
  const int count = 50;
  for (int r = 0; r < count; ++r) {
    Surface s;
    const auto up = uniforms(rng, gen.modes()), ua = uniforms(rng, gen.modes());
    gen.generate(up.data(), ua.data(), s);
    const auto c = surface_periodogram(s);
    for (std::size_t i = 0; i < c.size(); ++i) mean_c[i] += c[i] / count;
    for (std::size_t iy = 0; iy < n; ++iy) {
      const std::vector<double> row(s.heights.begin() + static_cast<std::ptrdiff_t>(iy * n),
                                    s.heights.begin() + static_cast<std::ptrdiff_t>((iy + 1) * n));
      const auto p = texture_test::periodogram(row, kD);  // rows are periodic: no window needed
      for (std::size_t j = 0; j < nh; ++j) mean_row[j] += p[j] / (count * static_cast<double>(n));
    }
  }
  // Radial bands: mean over the modes whose |q| falls in the band, realised against target.
  double worst2d = 0.0, worst_centre = 0.0, worst_modes = 0.0;
  int bands2d = 0;
  for (const auto& b : rollspec::spectral::third_octave_bands(spatial_frequency_from_wavenumber(dq), 0.5 / kD)) {
    const double lo = wavenumber_from_spatial_frequency(b.lower), hi = wavenumber_from_spatial_frequency(b.upper);
    double se = 0.0, st = 0.0, modes = 0.0;
    for (std::size_t iy = 0; iy < n; ++iy)
      for (std::size_t ix = 0; ix < nh; ++ix) {
        const double qy =
            dq * (iy <= n / 2 ? static_cast<double>(iy) : static_cast<double>(iy) - static_cast<double>(n));
        const double q = std::hypot(dq * static_cast<double>(ix), qy);
        if (q < lo || q >= hi || gen.mode_psd()[iy * nh + ix] <= 0.0) continue;
        const double w = (ix == 0) ? 1.0 : 2.0;
        se += w * mean_c[iy * nh + ix];
        st += w * gen.mode_psd()[iy * nh + ix];
        modes += w;
      }
    if (modes < 20) continue;  // each band mean has >= 20 modes x 50 surfaces x 2 dof
    const double d = texture_test::db(se / st);
    if (std::abs(d) > worst2d) {
      worst2d = std::abs(d);
      worst_centre = b.centre;
      worst_modes = modes;
    }
    CHECK(std::abs(d) <= 0.5);
    ++bands2d;
  }
  MESSAGE("radial 2D PSD: " << bands2d << " bands, worst |dL| = " << worst2d << " dB in the band at " << worst_centre
                            << " cycles/m (" << worst_modes << " modes, half of them conjugates)");
  CHECK(bands2d >= 8);

  // Rows cut from the surfaces against the line PSD G of the model, bands from 4 dq up to pi/dx.
  std::vector<double> target(nh);
  for (std::size_t j = 0; j < nh; ++j) target[j] = j ? model(dq * static_cast<double>(j)) : 0.0;
  const double dn = spatial_frequency_from_wavenumber(dq);
  const auto bands = texture_test::compare_bands(mean_row, target, dn, 4.0 * dn, 0.5 / kD, 0.0);
  double worst1d = 0.0;
  for (const auto& b : bands) {
    worst1d = std::max(worst1d, std::abs(b.delta_db));
    CHECK(std::abs(b.delta_db) <= 1.0);
  }
  MESSAGE("rows vs line PSD: " << bands.size() << " bands " << bands.front().centre_n << " .. " << bands.back().centre_n
                               << " cycles/m, worst |dL| = " << worst1d << " dB");
  CHECK(bands.size() >= 8);
}

TEST_CASE("anisotropy ratio 4 stretches the correlation lengths 2x in x and 1/2 in y, rms kept") {
  const SelfAffinePsd model(
      SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (16.0 * kD), M_PI / (4.0 * kD), RmsTarget::height, 0.2e-6});
  const SpectralSurfaceGenerator iso(model.to_psd(),
                                     SpectralSurfaceSpec{256, 256, kD, kD, Amplitudes::rayleigh, 1.0, false, 100});
  const SpectralSurfaceGenerator ani(model.to_psd(),
                                     SpectralSurfaceSpec{256, 256, kD, kD, Amplitudes::rayleigh, 4.0, false, 100});
  CHECK(ani.target_variance() == doctest::Approx(iso.target_variance()).epsilon(0.02));
  std::mt19937_64 rng(6);
  double lx_i = 0, ly_i = 0, lx_a = 0, ly_a = 0;
  for (int r = 0; r < 10; ++r) {
    const auto up = uniforms(rng, iso.modes()), ua = uniforms(rng, iso.modes());
    Surface a, b;
    iso.generate(up.data(), ua.data(), a);
    ani.generate(up.data(), ua.data(), b);
    const auto sa = surface_statistics(a), sb = surface_statistics(b);
    lx_i += sa.correlation_length_x;
    ly_i += sa.correlation_length_y;
    lx_a += sb.correlation_length_x;
    ly_a += sb.correlation_length_y;
  }
  MESSAGE("isotropic l_x/l_y = " << lx_i / ly_i << "; anisotropic l_x / l_x,iso = " << lx_a / lx_i
                                 << ", l_y / l_y,iso = " << ly_a / ly_i);
  CHECK(lx_i / ly_i == doctest::Approx(1.0).epsilon(0.1));
  CHECK(lx_a / lx_i == doctest::Approx(2.0).epsilon(0.1));
  CHECK(ly_a / ly_i == doctest::Approx(0.5).epsilon(0.1));
}

TEST_CASE("spectral surface refuses a grid that cannot hold the PSD's k_max") {
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 1e5, 1e7, RmsTarget::height, 1e-6});
  CHECK_THROWS_WITH_AS(SpectralSurfaceGenerator(
                           model.to_psd(), SpectralSurfaceSpec{64, 64, kD, kD, Amplitudes::rayleigh, 1.0, false, 100}),
                       doctest::Contains("refine the grid"), UnresolvedPsd);
  CHECK_THROWS_AS(SpectralSurfaceGenerator(surface_psd().to_psd(),
                                           SpectralSurfaceSpec{63, 64, kD, kD, Amplitudes::rayleigh, 1.0, false, 100}),
                  std::invalid_argument);
}
