// PSD from measured short profiles (seed 001 §3.1: 15 profiles of 15 mm; seed 002 §4.2:
// 0.02 mm grid, quadratic surface removal, 3-point median filter).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <limits>
#include <random>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
Profile make_profile(const std::vector<double>& z, double dx, double x0 = 0.0) {
  Profile p;
  p.z = z;
  p.x.resize(z.size());
  for (std::size_t i = 0; i < z.size(); ++i) p.x[i] = x0 + dx * static_cast<double>(i);
  return p;
}
}  // namespace

TEST_CASE("profile PSD recovers the PSD the profiles were drawn from, within 1 dB per resolved band") {
  // 15 mm profiles at 0.02 mm (750 samples), cut from long Rayleigh textures of a known PSD:
  // H = 0.8, roll-off at 2 mm wavelength, 0.5 um rms, cut off at the Nyquist wavenumber.
  const double dx = 2e-5;
  const std::size_t n_prof = 750, n_long = 1 << 16, per_line = n_long / n_prof;
  const SelfAffinePsd truth(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 2e-3, M_PI / dx, RmsTarget::height, 0.5e-6});
  const LineTextureGenerator gen(truth.to_psd(), LineTextureSpec{n_long, dx, 0, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(77);
  std::vector<Profile> profiles;
  for (int line = 0; line < 3; ++line) {
    const auto h = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
    for (std::size_t p = 0; p < per_line; ++p) {
      std::vector<double> z(h.begin() + static_cast<std::ptrdiff_t>(p * n_prof),
                            h.begin() + static_cast<std::ptrdiff_t>((p + 1) * n_prof));
      for (std::size_t i = 0; i < z.size(); ++i)
        z[i] += 3e-6 + 1e-4 * static_cast<double>(i) * dx;  // offset + tilt, removed by Eq. 15
      profiles.push_back(make_profile(z, dx, 0.1 * static_cast<double>(p)));
    }
  }
  const EstimatedPsd est = profile_psd(profiles);
  CHECK(est.profiles == 3 * per_line);
  CHECK(est.samples == n_prof);
  std::vector<double> target(est.psd.size());
  for (std::size_t j = 0; j < target.size(); ++j) target[j] = truth(est.wavenumber[j]);
  // Resolved range: from 8 profile fundamentals (1/15 mm each, below that the Hann window's
  // 4-bin main lobe and the trend removal bias the estimate) up to the Nyquist frequency 1/(2 dx).
  const double dn = spatial_frequency_from_wavenumber(est.dk);
  const auto bands = texture_test::compare_bands(est.psd, target, dn, 8.0 * dn, 0.5 / dx, 0.0);
  REQUIRE(bands.size() >= 10);
  double worst = 0.0;
  for (const auto& b : bands) {
    worst = std::max(worst, std::abs(b.delta_db));
    CHECK(std::abs(b.delta_db) <= 1.0);
  }
  MESSAGE(est.profiles << " profiles; " << bands.size() << " bands " << bands.front().centre_n << " .. "
                       << bands.back().centre_n << " cycles/m; worst |dL| = " << worst << " dB");
}

TEST_CASE("profile PSD: density scaling, sum_j G_j dk equals the variance of white noise") {
  std::mt19937_64 rng(4);
  std::vector<Profile> profiles;
  for (int p = 0; p < 400; ++p) {
    const auto u = uniforms(rng, 512);
    std::vector<double> z(256);
    for (std::size_t i = 0; i < z.size(); ++i)  // Box-Muller, sigma = 1 um
      z[i] = 1e-6 * std::sqrt(-2.0 * std::log(u[2 * i])) * std::cos(2.0 * M_PI * u[2 * i + 1]);
    profiles.push_back(make_profile(z, 1e-5));
  }
  const EstimatedPsd est = profile_psd(profiles);
  double var = 0.0;
  for (double g : est.psd) var += g * est.dk;
  CHECK(var == doctest::Approx(1e-12).epsilon(0.02).scale(0));  // 400 x 256 samples: ~0.5 % scatter
}

TEST_CASE("trend and quadratic-surface removal are exact on polynomials; 3-point median filter") {
  std::vector<double> z(20);
  for (std::size_t i = 0; i < z.size(); ++i) z[i] = 4.0 - 0.3 * static_cast<double>(i);
  remove_linear_trend(z);
  for (double v : z) CHECK(std::abs(v) < 1e-13);

  Surface m(12, 9, 1e-5, 2e-5);
  for (std::size_t iy = 0; iy < m.ny; ++iy)
    for (std::size_t ix = 0; ix < m.nx; ++ix) {
      const double x = static_cast<double>(ix), y = static_cast<double>(iy);
      m.at(ix, iy) = 1.0 + 0.2 * x - 0.1 * y + 0.03 * x * x - 0.02 * x * y + 0.05 * y * y;
    }
  remove_quadratic_surface(m);
  for (double v : m.heights) CHECK(std::abs(v) < 1e-12);

  std::vector<double> spike{0.0, 0.0, 5.0, 0.0, 1.0, 2.0, 3.0};
  median_filter3(spike);
  CHECK(spike == std::vector<double>{0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 3.0});
}

TEST_CASE("map PSD: rows of a 2D map are the profiles after the quadratic fit") {
  const double dx = 2e-5;
  const SelfAffinePsd truth(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 1e-3, M_PI / dx, RmsTarget::height, 0.5e-6});
  const LineTextureGenerator gen(truth.to_psd(), LineTextureSpec{512, dx, 0, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(9);
  Surface map(512, 64, dx, dx);
  for (std::size_t iy = 0; iy < map.ny; ++iy) {
    const auto h = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
    for (std::size_t ix = 0; ix < map.nx; ++ix) map.at(ix, iy) = h[ix] + 1e-9 * static_cast<double>(ix * ix);
  }
  const EstimatedPsd est = map_psd(map, ProfilePsdOptions{true});
  // A pure quadratic map has no roughness left after Eq. 15 (2D): the whole estimate vanishes.
  Surface bowl(64, 16, dx, dx);
  for (std::size_t iy = 0; iy < bowl.ny; ++iy)
    for (std::size_t ix = 0; ix < bowl.nx; ++ix)
      bowl.at(ix, iy) = 1e-6 * (1.0 + 0.3 * static_cast<double>(ix * ix) - 0.2 * static_cast<double>(ix * iy) +
                                0.1 * static_cast<double>(iy * iy));
  // Round-off only: the estimate's variance is far below the bowl's own (double precision, 1e-16
  // in height, is 1e-32 in variance).
  double bowl_mean = 0.0, bowl_variance = 0.0, leftover = 0.0;
  for (double h : bowl.heights) bowl_mean += h / static_cast<double>(bowl.heights.size());
  for (double h : bowl.heights)
    bowl_variance += (h - bowl_mean) * (h - bowl_mean) / static_cast<double>(bowl.heights.size());
  const EstimatedPsd flat = map_psd(bowl);
  for (double g : flat.psd) leftover += g * flat.dk;
  MESSAGE("quadratic map: estimate variance / map variance = " << leftover / bowl_variance);
  CHECK(leftover < 1e-28 * bowl_variance);
  CHECK(est.profiles == 64);
  CHECK(est.samples == 512);
  CHECK(est.dk == doctest::Approx(2.0 * M_PI / (512 * dx)));
}

TEST_CASE("profile PSD refuses bad input with clear messages") {
  const double dx = 1e-5;
  const std::vector<double> z8(8, 0.0), z7(7, 0.0), z16(16, 0.0);
  CHECK_THROWS_WITH_AS(profile_psd({}), doctest::Contains("at least 1 profile, got none"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(profile_psd({make_profile(z8, dx), make_profile(z7, dx)}),
                       doctest::Contains("profile 1 has 7 samples; at least 8"), std::invalid_argument);
  Profile bent = make_profile(z16, dx);
  bent.x[5] += 0.3 * dx;
  CHECK_THROWS_WITH_AS(profile_psd({make_profile(z16, dx), bent}),
                       doctest::Contains("profile 1: non-uniform spacing at sample 5"), std::invalid_argument);
  Profile bad = make_profile(z16, dx);
  bad.z[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(profile_psd({bad, make_profile(z16, dx)}),
                       doctest::Contains("profile 0: sample 3 is not finite"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(profile_psd({make_profile(z16, dx), make_profile(z8, dx)}),
                       doctest::Contains("periodograms are averaged on one grid"), std::invalid_argument);
  Surface thin(16, 1, dx, dx);
  CHECK_THROWS_WITH_AS(map_psd(thin), doctest::Contains("at least 2 rows"), std::invalid_argument);
}

// A steep scan: a Rayleigh line with a bow whose variance dwarfs the roughness, as form does on
// real stylus scans (hfm-1: 99.5 % of the variance below 4 fundamentals).
TEST_CASE("one scan is an estimate at its periodogram's own level (Eq. 43); the rest of its variance is V_u (Eq. 44)") {
  const double dx = 1e-6;
  const std::size_t n = 2048;
  const SelfAffinePsd truth(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 50e-6, M_PI / dx, RmsTarget::height, 0.1e-6});
  const LineTextureGenerator gen(truth.to_psd(), LineTextureSpec{n, dx, 4 * n, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(31);
  auto z = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(n - 1) - 0.5;
    z[i] += 2e-5 * u * u + 5e-7 * u;  // bow and tilt
  }
  const EstimatedPsd est = profile_psd({make_profile(z, dx)});
  CHECK(est.profiles == 1);
  // Eq. 42: the first octave whose leakage from the unresolved variance is at most 10 % of its power.
  const auto leak = longest_wave_leakage(n, dx);
  const auto clears = [&](std::size_t j) {
    double above = 0.0, leaked = 0.0, measured = 0.0;
    for (std::size_t i = j; i < est.psd.size(); ++i) above += est.psd[i] * est.dk;
    for (std::size_t i = j; i < 2 * j; ++i) {
      leaked += leak[i];
      measured += est.psd[i];
    }
    return (est.variance - above) * leaked <= kResolvedLeakage * measured;
  };
  CHECK(est.first_resolved >= kFirstResolvedBin);
  CHECK(clears(est.first_resolved));
  for (std::size_t j = kFirstResolvedBin; j < est.first_resolved; ++j) CHECK_FALSE(clears(j));
  MESSAGE("bowed scan: first resolved bin " << est.first_resolved);
  std::vector<double> d = z;
  remove_linear_trend(d);
  const auto own = hann_periodogram(d, dx);
  CHECK(est.psd[0] == 0.0);
  for (std::size_t j = 1; j < own.size(); ++j) CHECK(std::abs(est.psd[j] / own[j] - 1.0) < 1e-12);
  double mean = 0.0, var = 0.0, resolved = 0.0, held = 0.0;
  for (double v : d) mean += v / static_cast<double>(n);
  for (double v : d) var += (v - mean) * (v - mean) / static_cast<double>(n);
  for (std::size_t j = 1; j < own.size(); ++j) held += own[j] * est.dk;
  for (std::size_t j = est.first_resolved; j < own.size(); ++j) resolved += own[j] * est.dk;
  CHECK(std::abs(est.variance / var - 1.0) < 1e-12);
  CHECK(std::abs(est.resolved_variance() / resolved - 1.0) < 1e-12);
  CHECK(std::abs(est.unresolved_variance() / (var - resolved) - 1.0) < 1e-12);
  // The old level rule scaled every bin by V / sum_{j>=1} G_j dk: here far from 1, since the window
  // hides the bow's variance in the DC bin. Eq. 43 keeps the bins where the periodogram put them.
  MESSAGE("bowed scan: unresolved " << est.unresolved_variance() / var << " of the variance; the old rule would move "
                                    << "every bin by " << texture_test::db(var / held) << " dB");
  CHECK(std::abs(texture_test::db(var / held)) > 2.0);
}

TEST_CASE("Eq. 42's leakage of the longest wave: scipy's Hann periodogram after a linear detrend agrees") {
  // scipy.signal.periodogram(cos(2 pi i / 4096 + phi), window='hann', detrend='linear'), 64 phases:
  // the share of the wave's power in bins [4, 8) is 4.67e-5, in [8, 16) 1.01e-6.
  const std::size_t n = 4096;
  const double dx = 1e-6, dk = 2.0 * M_PI / (static_cast<double>(n) * dx);
  const auto leak = longest_wave_leakage(n, dx);
  double first = 0.0, second = 0.0;
  for (std::size_t j = 4; j < 8; ++j) first += leak[j] * dk;
  for (std::size_t j = 8; j < 16; ++j) second += leak[j] * dk;
  CHECK(std::abs(first / 4.67e-5 - 1.0) < 0.01);
  CHECK(std::abs(second / 1.01e-6 - 1.0) < 0.01);
  for (std::size_t j = 3; j < 40; ++j) CHECK(leak[j + 1] < leak[j]);
}

TEST_CASE("Hann periodogram (Eq. 16) equals a plain DFT sum (reference oracle); table from the estimate") {
  std::mt19937_64 rng(21);
  const std::size_t n = 64;
  const double dx = 3e-5;
  const auto z = uniforms(rng, n);
  const auto fast = hann_periodogram(z, dx);
  double sw2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n));
    sw2 += w * w;
  }
  for (std::size_t j = 0; j <= n / 2; ++j) {
    double re = 0.0, im = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n));
      const double arg = 2.0 * M_PI * static_cast<double>(j * i) / static_cast<double>(n);
      re += w * z[i] * std::cos(arg);
      im -= w * z[i] * std::sin(arg);
    }
    const double c = (j == 0 || j == n / 2) ? 1.0 : 2.0;
    CHECK(fast[j] == doctest::Approx(c * dx * (re * re + im * im) / (2.0 * M_PI * sw2)).epsilon(1e-12).scale(0));
  }
  std::vector<Profile> ps{make_profile(z, dx), make_profile(uniforms(rng, n), dx)};
  const EstimatedPsd est = profile_psd(ps);
  const TabulatedPsd t = estimated_psd_table(est, Extension::zero);
  CHECK(t.k_min() == doctest::Approx(est.dk));
  CHECK(t(est.wavenumber[5]) == doctest::Approx(est.psd[5]).scale(0));
  CHECK(t(0.5 * est.dk) == 0.0);
}

TEST_CASE("map PSD of tilted, bowed spectral surfaces recovers the line PSD within 1 dB per resolved band") {
  // 10 surfaces of 512 x 64 at 1 um (rows 0.512 mm long) with a quadratic bow added; the rows are
  // profiles along x. Resolved range as for 1D profiles: 8 row fundamentals up to 1/(2 dx).
  const double d = 1e-6;
  const SelfAffinePsd truth(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (40.0 * d), M_PI / d, RmsTarget::height, 0.2e-6});
  const SpectralSurfaceGenerator gen(truth.to_psd(),
                                     SpectralSurfaceSpec{512, 64, d, d, Amplitudes::rayleigh, 1.0, false, 100});
  std::mt19937_64 rng(10);
  std::vector<double> mean;
  EstimatedPsd est;
  for (int r = 0; r < 10; ++r) {
    Surface s;
    gen.generate(uniforms(rng, gen.modes()).data(), uniforms(rng, gen.modes()).data(), s);
    for (std::size_t iy = 0; iy < s.ny; ++iy)
      for (std::size_t ix = 0; ix < s.nx; ++ix) {
        const double x = static_cast<double>(ix) * d, y = static_cast<double>(iy) * d;
        s.at(ix, iy) += 1e-6 + 2e-3 * x - 1e-3 * y + 3.0 * x * x + 1.0 * x * y - 2.0 * y * y;
      }
    est = map_psd(s);
    if (mean.empty()) mean.assign(est.psd.size(), 0.0);
    for (std::size_t j = 0; j < mean.size(); ++j) mean[j] += est.psd[j] / 10.0;
  }
  std::vector<double> target(mean.size());
  for (std::size_t j = 0; j < target.size(); ++j) target[j] = truth(est.wavenumber[j]);
  const double dn = spatial_frequency_from_wavenumber(est.dk);
  const auto bands = texture_test::compare_bands(mean, target, dn, 8.0 * dn, 0.5 / d, 0.0);
  REQUIRE(bands.size() >= 10);
  double worst = 0.0;
  for (const auto& b : bands) {
    worst = std::max(worst, std::abs(b.delta_db));
    CHECK(std::abs(b.delta_db) <= 1.0);
  }
  MESSAGE("map PSD: 640 rows; " << bands.size() << " bands " << bands.front().centre_n << " .. "
                                << bands.back().centre_n << " cycles/m; worst |dL| = " << worst << " dB");
}
