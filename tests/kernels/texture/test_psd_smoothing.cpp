// Surfaces from a PSD estimated from few noisy profiles keep the profiles' rms once the estimate
// is band-averaged (README Eq. 33-35); seed surfaces take the profiles' sigma (seed 001 Eq. 10).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/measured_psd.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd.hpp"
#include "kernels/texture/psd_smoothing.hpp"
#include "kernels/texture/seed_surface.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "kernels/texture/statistics.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
// P profiles of n samples at dx, each a window of a longer Rayleigh line (so not periodic).
std::vector<Profile> noisy_profiles(const Psd& psd, std::size_t count, std::size_t n, double dx, std::uint64_t seed) {
  const LineTextureGenerator gen(psd, LineTextureSpec{n, dx, 4 * n, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(seed);
  std::vector<Profile> out(count);
  for (auto& p : out) {
    p.z = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
    p.x.resize(n);
    for (std::size_t i = 0; i < n; ++i) p.x[i] = dx * static_cast<double>(i);
  }
  return out;
}

// Mean rms of `count` spectral surfaces of the table; clamped: the share of Eq. 19 nodes clamped at 0.
double spectral_rms(const Psd& psd, std::size_t side, double dx, std::mt19937_64& rng, double* clamped = nullptr,
                    std::size_t count = 4) {
  SpectralSurfaceSpec spec;
  spec.nx = spec.ny = side;
  spec.dx = spec.dy = dx;
  const SpectralSurfaceGenerator gen(psd, spec);
  if (clamped) *clamped = gen.isotropic_psd().clamped_fraction();
  double acc = 0.0;
  Surface s;
  for (std::size_t r = 0; r < count; ++r) {
    gen.generate(uniforms(rng, gen.modes()).data(), uniforms(rng, gen.modes()).data(), s);
    acc += surface_statistics(s).rms;
  }
  return acc / static_cast<double>(count);
}
}  // namespace

TEST_CASE("band averages keep the estimate's power and span its range") {
  EstimatedPsd e;
  e.dk = 3.0;
  e.psd.resize(1001);
  std::mt19937_64 rng(5);
  for (double& g : e.psd) g = 1e-20 * uniforms(rng, 1)[0];
  const BandAveragedPsd b = band_averaged_psd(e, PsdBands{3, 4, 1});
  double raw = 0.0, banded = 0.0;
  for (std::size_t j = 1; j < e.psd.size(); ++j) raw += e.psd[j];
  for (std::size_t i = 0; i < b.psd.size(); ++i) {
    CHECK(b.last[i] - b.first[i] + 1 >= 4);
    if (i) CHECK(b.first[i] == b.last[i - 1] + 1);                         // contiguous, no bin twice
    banded += b.psd[i] * static_cast<double>(b.last[i] - b.first[i] + 1);  // Eq. 33
  }
  CHECK(b.first.front() == 1);
  CHECK(b.last.back() == 1000);
  // From a first resolved bin of 4: octaves of bins [4 2^m, 4 2^(m+1)) are unions of bands (Eq. 33), each
  // band of at least 4 bins.
  const BandAveragedPsd o = band_averaged_psd(e, PsdBands{3, 4, 4});
  for (std::size_t i = 0; i < o.psd.size(); ++i) {
    CHECK(o.last[i] - o.first[i] + 1 >= 4);
    if (i) CHECK(o.first[i] == o.last[i - 1] + 1);
  }
  for (std::size_t octave = 4; octave <= 512; octave *= 2) {
    bool starts = false;
    for (std::size_t f : o.first) starts = starts || f == octave;
    CHECK(starts);
  }
  CHECK(banded == doctest::Approx(raw).epsilon(1e-13).scale(0));
  CHECK(b.psd.size() < 40);  // 3 decades at 10 per decade, fewer where bands need 4 bins
  const TabulatedPsd t = smoothed_psd_table(e, Extension::error);
  CHECK(t.k_min() == doctest::Approx(1.5));  // the first band's lower edge (bin 1 covers [0.5, 1.5] dk)
  CHECK(t.k_max() == doctest::Approx(3000.0));
  CHECK(t.integral(t.k_min(), t.k_max()) == doctest::Approx(raw * e.dk).epsilon(1e-10).scale(0));  // Eq. 41
  CHECK_THROWS_AS(band_averaged_psd(e, PsdBands{3, 600, 1}), std::invalid_argument);
}

TEST_CASE("surfaces from a PSD estimated from 5, 15 and 50 profiles keep the profiles' rms") {
  // 4 mm profiles at 1 um of H = 0.8, roll-off at 20 um, 0.4 um rms up to the Nyquist wavenumber;
  // 128 x 128 surfaces at 1 um (the whole band above 1/128 um^-1 in 2D).
  const double dx = 1e-6;
  const std::size_t n = 4096, side = 128;
  const Psd truth =
      SelfAffinePsd(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 20e-6, M_PI / dx, RmsTarget::height, 0.4e-6}).to_psd();
  std::mt19937_64 rng(15);
  const double exact = spectral_rms(truth, side, dx, rng) / 0.4e-6;
  MESSAGE("surface rms / 0.4 um from the exact PSD: " << exact);
  for (const std::size_t count : {5u, 15u, 50u}) {
    const auto profiles = noisy_profiles(truth, count, n, dx, 1000 + count);
    const EstimatedPsd est = profile_psd(profiles);
    double clamp_raw = 0.0, clamp_smooth = 0.0;
    const double raw =
        spectral_rms(estimated_psd_table(est, Extension::zero).to_psd(), side, dx, rng, &clamp_raw) / est.sigma;
    const double smooth =
        spectral_rms(smoothed_psd_table(est, Extension::zero).to_psd(), side, dx, rng, &clamp_smooth) / est.sigma;
    double clamp_measured = 0.0;  // the generators' PSD: resolved band from j_r, unresolved cells (Eq. 45)
    const double measured =
        spectral_rms(measured_line_psd(est, Extension::zero), side, dx, rng, &clamp_measured) / est.sigma;
    MESSAGE(count << " profiles (sigma " << est.sigma << " m): surface rms / profile rms " << raw << " raw ("
                  << clamp_raw << " of Eq. 19 nodes clamped), " << smooth << " band-averaged (" << clamp_smooth << "), "
                  << measured << " with Eq. 45 (" << clamp_measured << ")");
    CHECK(std::abs(smooth - 1.0) < 0.1);
    CHECK(std::abs(measured - 1.0) < 0.1);
    CHECK(raw > 1.1);  // the raw periodogram table fails the same bound (README §5a): the test has teeth
    // Seed method: Eq. 30 with sigma = the profiles' sigma (seed 001 Eq. 10).
    SeedSurfaceRequest rq;
    rq.nx = rq.ny = side;
    rq.dx = rq.dy = dx;
    rq.correlation_x = rq.correlation_y = 10e-6;
    rq.sigma = est.sigma;
    const SeedSurfaceGenerator seed(smoothed_psd_table(est, Extension::zero).to_psd(), rq);
    Surface s;
    seed.generate(uniforms(rng, seed.random_count()).data(), s);
    CHECK(surface_statistics(s).rms == doctest::Approx(est.sigma).epsilon(1e-12).scale(0));
  }
}

// A measured spectrum as steep as real stylus scans (README §5a): half the variance in bin 1.
TEST_CASE("a steep estimate keeps every band's power in the table (Eq. 41) and on any grid (Eq. 14b)") {
  EstimatedPsd e;
  e.dk = 2.0;
  e.psd.resize(2401);
  for (std::size_t j = 1; j < e.psd.size(); ++j) e.psd[j] = 1e-18 * std::pow(static_cast<double>(j), -3.5);
  const BandAveragedPsd b = band_averaged_psd(e);
  const TabulatedPsd t = smoothed_psd_table(e, Extension::zero);
  double total = 0.0;
  for (std::size_t i = 0; i < b.psd.size(); ++i) {
    const double lo = e.dk * (static_cast<double>(b.first[i]) - 0.5);
    const double hi = i + 1 < b.psd.size() ? e.dk * (static_cast<double>(b.first[i + 1]) - 0.5) : t.k_max();
    const double power = b.psd[i] * static_cast<double>(b.last[i] - b.first[i] + 1) * e.dk;
    CHECK(t.integral(lo, hi) == doctest::Approx(power).epsilon(1e-9).scale(0));
    total += power;
  }
  CHECK(e.psd[1] * e.dk / total > 0.5);
  Psd psd = t.to_psd();
  psd.cell_average = true;
  Psd point = t.to_psd();
  double worst_point = 0.0;
  for (const double shrink : {1.0, 1.5, 2.3, 7.0}) {  // grids as long as the profile and longer
    const double dk = e.dk / shrink;
    const auto count = static_cast<std::size_t>(std::ceil(t.k_max() / dk)) + 2;
    double cells = 0.0, points = 0.0;
    const auto g = psd_at_harmonics(psd, dk, count), gp = psd_at_harmonics(point, dk, count);
    for (std::size_t j = 1; j < count; ++j) {
      cells += g[j] * dk;
      points += gp[j] * dk;
    }
    CHECK(cells == doctest::Approx(total).epsilon(1e-6).scale(0));
    worst_point = std::max(worst_point, std::abs(points / total - 1.0));
  }
  CHECK(worst_point > 0.05);  // what Eq. 14b is for: point samples of the steep first band miss by more
}
