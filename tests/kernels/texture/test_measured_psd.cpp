// The PSD the generators take from measured profiles (README Eq. 43-45): the resolved band at the
// periodogram's level, the unresolved variance apart in the scan's longest cell.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/measured_psd.hpp"
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
// A steep estimate (G_j ~ j^-3.5) whose scans hold `extra` times the periodogram's variance.
EstimatedPsd steep_estimate(double extra) {
  EstimatedPsd e;
  e.dk = 2.0;
  e.spacing = M_PI / (2400.0 * e.dk);
  e.samples = 4800;
  e.profiles = 1;
  e.first_resolved = 4;
  e.psd.assign(2401, 0.0);
  e.wavenumber.resize(e.psd.size());
  double held = 0.0;
  for (std::size_t j = 1; j < e.psd.size(); ++j) {
    e.psd[j] = 1e-18 * std::pow(static_cast<double>(j), -3.5);
    held += e.psd[j] * e.dk;
  }
  for (std::size_t j = 0; j < e.psd.size(); ++j) e.wavenumber[j] = e.dk * static_cast<double>(j);
  e.variance = extra * held;
  return e;
}

double rel(double a, double b) { return std::abs(a / b - 1.0); }

// Octave sums [2^m, 2^{m+1}) of bins from `first` up to the last whole octave.
std::vector<double> octaves(const std::vector<double>& g, std::size_t first) {
  std::vector<double> out;
  for (std::size_t j = first; 2 * j <= g.size() - 1; j *= 2) {
    double s = 0.0;
    for (std::size_t i = j; i < 2 * j; ++i) s += g[i];
    out.push_back(s);
  }
  return out;
}
}  // namespace

TEST_CASE("Eq. 45: the resolved band keeps its power, the unresolved variance sits below k_r on any grid") {
  const EstimatedPsd e = steep_estimate(3.0);
  const double vr = e.resolved_variance(), vu = e.unresolved_variance();
  CHECK(rel(vr + vu, e.variance) < 1e-12);
  const Psd psd = measured_line_psd(e, Extension::zero);
  CHECK(psd.cell_average);
  // The scan's own cells: bins >= j_r hold V_r (Eq. 41 per band), bins 1..3 hold V_u.
  const auto g = psd_at_harmonics(psd, e.dk, e.psd.size());
  double resolved = 0.0, below = 0.0;
  for (std::size_t j = 1; j < g.size(); ++j) (j >= e.first_resolved ? resolved : below) += g[j] * e.dk;
  CHECK(rel(resolved, vr) < 1e-9);
  CHECK(rel(below, vu) < 1e-9);
  // Large V_u: the resolved level continued flat, the rest in the longest cell (bin 1).
  const UnresolvedCells u = unresolved_cells(e, psd(e.dk * 3.6));
  CHECK(rel(g[2], u.level) < 1e-12);
  CHECK(rel(g[3], u.level) < 1e-12);
  CHECK(rel(g[1], u.cell_level) < 1e-12);
  CHECK(rel(u.level * 2.0 * e.dk + u.cell_level * e.dk, vu) < 1e-12);
  CHECK(u.cell_level > 100.0 * u.level);
  // Longer grids keep it all (cells of Eq. 14b); below dk/2 the extension decides.
  for (const double shrink : {1.5, 2.3, 7.0}) {
    const double dk = e.dk / shrink;
    const auto h = psd_at_harmonics(psd, dk, static_cast<std::size_t>(std::ceil(2401.0 * shrink)) + 2);
    double total = 0.0;
    for (double v : h) total += v * dk;
    CHECK(rel(total, e.variance) < 1e-6);
  }
  CHECK(psd(0.25 * e.dk) == 0.0);
  CHECK(measured_line_psd(e, Extension::constant)(0.25 * e.dk) == u.cell_level);
  CHECK_THROWS_WITH_AS(measured_line_psd(e, Extension::error)(0.25 * e.dk),
                       doctest::Contains("the measured profiles cover k = 1 .. 4800 rad/m"), std::domain_error);
}

TEST_CASE("Eq. 45: a flat spectrum's few unresolved bins continue its level, nothing piles up in bin 1") {
  EstimatedPsd e = steep_estimate(1.0);
  for (double& g : e.psd) g = g > 0.0 ? 1e-20 : 0.0;
  e.variance = 1e-20 * e.dk * 2400.0;  // every bin at the flat level
  const Psd psd = measured_line_psd(e, Extension::zero);
  const UnresolvedCells u = unresolved_cells(e, psd(e.dk * 3.6));
  CHECK(rel(u.level, 1e-20) < 1e-9);  // the table's node after Eq. 41's fixed point
  CHECK(rel(u.cell_level, u.level) < 1e-9);
}

// Bowed scans (the bow holds most of their variance, as form does on real stylus scans): lines made
// from their estimate and analysed like them (trend removed, Hann) show the scans' mean periodogram in
// every resolved octave, and their variance. Four scans, so that one scan's chi-square scatter, which
// the band averages of Eq. 33 smooth across octave edges, stays well inside the 1 dB. The old level
// rule (Eq. 17b) moved every octave by 10 log10(V / sum_{j>=1} G_j dk), beyond 2 dB here.
TEST_CASE("lines from bowed scans show their periodogram's octaves within 1 dB and their variance within 5 %") {
  const double dx = 1e-6;
  const std::size_t n = 4096, lines = 100;
  const SelfAffinePsd truth(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 30e-6, M_PI / dx, RmsTarget::height, 0.05e-6});
  const LineTextureGenerator scan_gen(truth.to_psd(), LineTextureSpec{n, dx, 4 * n, Amplitudes::rayleigh, false});
  std::mt19937_64 rng(43);
  std::vector<Profile> scans(4);
  for (Profile& scan : scans) {
    scan.z = scan_gen.generate(uniforms(rng, scan_gen.harmonics()), uniforms(rng, scan_gen.harmonics()));
    scan.x.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double u = static_cast<double>(i) / static_cast<double>(n - 1) - 0.5;
      scan.x[i] = dx * static_cast<double>(i);
      scan.z[i] += 4e-6 * u * u;
    }
  }
  const EstimatedPsd est = profile_psd(scans);
  double held = 0.0;
  for (std::size_t j = 1; j < est.psd.size(); ++j) held += est.psd[j] * est.dk;
  const double old_shift = texture_test::db(est.variance / held);
  const LineTextureGenerator gen(measured_line_psd(est, Extension::zero),
                                 LineTextureSpec{n, dx, 0, Amplitudes::rayleigh, false});
  std::vector<double> mean(est.psd.size(), 0.0);
  double variance = 0.0, variance2 = 0.0;
  for (std::size_t r = 0; r < lines; ++r) {
    auto h = gen.generate(uniforms(rng, gen.harmonics()), uniforms(rng, gen.harmonics()));
    double m = 0.0, v = 0.0;
    for (double z : h) m += z / static_cast<double>(n);
    for (double z : h) v += (z - m) * (z - m) / static_cast<double>(n);
    variance += v / static_cast<double>(lines);
    variance2 += v * v / static_cast<double>(lines);
    remove_linear_trend(h);
    const auto p = hann_periodogram(h, dx);
    for (std::size_t j = 0; j < p.size(); ++j) mean[j] += p[j] / static_cast<double>(lines);
  }
  const auto scan_oct = octaves(est.psd, est.first_resolved), line_oct = octaves(mean, est.first_resolved);
  REQUIRE(scan_oct.size() >= 8);
  double worst = 0.0, worst_old = 0.0;
  std::string levels;
  for (std::size_t i = 0; i < scan_oct.size(); ++i) {
    const double d = texture_test::db(line_oct[i] / scan_oct[i]);
    worst = std::max(worst, std::abs(d));
    worst_old = std::max(worst_old, std::abs(d + old_shift));
    levels += " " + std::to_string(d);
    CHECK(std::abs(d) <= 1.0);
  }
  MESSAGE("octave levels of the lines - the scan's, dB:" << levels);
  const double se = std::sqrt((variance2 - variance * variance) / static_cast<double>(lines));
  MESSAGE("bowed scans: first resolved bin "
          << est.first_resolved << ", unresolved " << est.unresolved_variance() / est.variance
          << " of the variance; worst octave " << worst << " dB; lines' variance " << variance / est.variance << " +- "
          << se / est.variance << " of the scan's; the old level rule: " << old_shift << " dB in every octave");
  CHECK(std::abs(variance / est.variance - 1.0) <= 0.05 + 2.0 * se / est.variance);
  CHECK(worst_old > 1.0);  // the test has teeth: the old level rule fails it
}
