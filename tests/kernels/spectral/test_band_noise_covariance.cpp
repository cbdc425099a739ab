// D-33e: the logger noise's covariance between band averages of one roll, given the roll's signal. The forms Q_b x
// against the polarisation of the plain estimator, the traces against sums of unit vectors' forms, and Monte-Carlo
// noise on a coherent signal (a slow transient whose bands are narrower than a bin) against the exact moments.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/band_noise_covariance.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "philox_draws.hpp"
#include "welch_config.hpp"

using namespace rollspec::spectral;
using rollspec::spectral::testing::welch_config;

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

TEST_CASE("the forms, their traces and products match the plain estimator's polarisation") {
  for (const bool detrend : {true, false})
    for (const std::size_t overlap : {std::size_t{0}, std::size_t{16}, std::size_t{24}}) {
      WelchConfig c = welch_config(320.0, 32, overlap);  // bins of 10 Hz
      c.detrend = detrend ? Detrend::constant : Detrend::none;
      const std::size_t n = 90;
      // At DC (the mean's lobe), two bands inside and across one bin, a wide band, the Nyquist bin.
      const std::vector<double> lo = {0.0, 8.0, 12.0, 33.0, 150.0}, hi = {7.0, 12.0, 19.0, 97.0, 160.0};
      const BandNoiseCovariance cov(c, n, lo, hi);
      testing::PhiloxNormals normal(7 + overlap);
      std::vector<double> x(n);
      for (std::size_t t = 0; t < n; ++t) x[t] = normal.next() + std::sin(0.07 * static_cast<double>(t));
      const std::size_t p = lo.size();
      std::vector<std::vector<double>> q(p);
      for (std::size_t b = 0; b < p; ++b) q[b] = band_form_reference(c, x.data(), n, lo[b], hi[b]);
      const std::vector<double> g = cov.gram(x.data());
      std::vector<double> tr(p, 0.0), trq(p * p, 0.0);
      std::vector<double> e(n, 0.0);
      for (std::size_t t = 0; t < n; ++t) {  // Q_b e_t for every t: tr Q_b = sum_t (Q_b e_t)_t, tr Q_b Q_c likewise
        e[t] = 1.0;
        std::vector<std::vector<double>> col(p);
        for (std::size_t b = 0; b < p; ++b) {
          col[b] = band_form_reference(c, e.data(), n, lo[b], hi[b]);
          tr[b] += col[b][t];
        }
        for (std::size_t b = 0; b < p; ++b)
          for (std::size_t d = 0; d < p; ++d) trq[b * p + d] += dot(col[b], col[d]);
        e[t] = 0.0;
      }
      for (std::size_t b = 0; b < p; ++b) {
        CHECK(cov.trace()[b] == doctest::Approx(tr[b]).epsilon(1e-10));
        for (std::size_t d = 0; d < p; ++d) {
          const double scale = std::sqrt(g[b * p + b] * g[d * p + d]);
          CHECK(g[b * p + d] == doctest::Approx(dot(q[b], q[d])).epsilon(1e-9 * scale / std::fabs(g[b * p + d])));
          const double ts = std::sqrt(trq[b * p + b] * trq[d * p + d]);
          CHECK(cov.trace_product()[b * p + d] == doctest::Approx(trq[b * p + d]).epsilon(1e-10).scale(ts));
        }
      }
    }
}

TEST_CASE("BandDof's pair sums: one band's give its dof; two bands' are symmetric") {
  const WelchConfig c = welch_config(1000.0, 64, 48);
  const BandDof dof(c);
  for (const std::size_t n : {std::size_t{64}, std::size_t{100}, std::size_t{333}})
    for (const auto& band : std::vector<std::pair<double, double>>{{0.0, 20.0}, {40.0, 90.0}, {100.0, 480.0}}) {
      const double e = dof.mean_sum(band.first, band.second),
                   v = dof.pair_sum(n, band.first, band.second, band.first, band.second);
      CHECK(2.0 * e * e / v == doctest::Approx(dof(n, band.first, band.second)).epsilon(1e-12));
      CHECK(dof.pair_sum(n, band.first, band.second, 30.0, 70.0) ==
            doctest::Approx(dof.pair_sum(n, 30.0, 70.0, band.first, band.second)).epsilon(1e-12));
    }
  CHECK(dof.pair_sum(63, 40.0, 90.0, 40.0, 90.0) == 0.0);  // shorter than a segment
}

TEST_CASE("Monte-Carlo: noise on a coherent transient has the covariance of the roll's own forms, not 4 S N / nu") {
  // A slow bump (the ball's weight crossing the span) and a decaying tone, as in the bands below a beam's first
  // mode: bands narrower than a bin share it. 6000 draws of white noise on the one signal: the sample covariance's
  // relative standard error is about 2 %, the tolerance 8 % (on the diagonal; off it, 0.05 of the diagonals).
  const WelchConfig c = welch_config(640.0, 64, 32);  // bins of 10 Hz
  const WelchPlan plan(c);
  WelchWorkspace ws(c.segment);
  const std::size_t n = 288, draws = 6000;
  const std::vector<double> lo = {11.2, 14.1, 17.8, 44.7}, hi = {14.1, 17.8, 22.4, 56.2};
  const std::size_t p = lo.size();
  std::vector<double> s(n);
  for (std::size_t t = 0; t < n; ++t) {
    const double u = static_cast<double>(t) / static_cast<double>(n), time = static_cast<double>(t) / c.sample_rate;
    s[t] = std::sin(M_PI * u) * std::sin(M_PI * u) + 0.05 * std::exp(-3.0 * u) * std::sin(2.0 * M_PI * 36.0 * time);
  }
  const double sigma2 = 1e-4;
  const BandNoiseCovariance cov(c, n, lo, hi);
  const std::vector<double> g = cov.gram(s.data());
  std::vector<double> exact(p * p);
  for (std::size_t i = 0; i < p * p; ++i)
    exact[i] = 4.0 * sigma2 * g[i] + 2.0 * sigma2 * sigma2 * cov.trace_product()[i];

  testing::PhiloxNormals normal(48);
  std::vector<double> x(n), psd(plan.n_freq()), sum(p, 0.0), prod(p * p, 0.0), estimate(p * p, 0.0);
  for (std::size_t d = 0; d < draws; ++d) {
    for (std::size_t t = 0; t < n; ++t) x[t] = s[t] + std::sqrt(sigma2) * normal.next();
    plan.psd(x.data(), n, psd.data(), ws);
    std::vector<double> band(p);
    for (std::size_t b = 0; b < p; ++b)
      band[b] = band_average(psd.data(), psd.size(), plan.frequency_step(), lo[b], hi[b]);
    for (std::size_t b = 0; b < p; ++b) {
      sum[b] += band[b];
      for (std::size_t e = 0; e < p; ++e) prod[b * p + e] += band[b] * band[e];
    }
    if (d < 400) {  // the estimate from the noisy roll itself, unbiased
      const std::vector<double> one = cov.covariance(x.data(), std::vector<double>(p, sigma2));
      for (std::size_t i = 0; i < p * p; ++i) estimate[i] += one[i] / 400.0;
    }
  }
  const BandDof dof(c);
  const double dn = static_cast<double>(draws);
  for (std::size_t b = 0; b < p; ++b) {
    const double mc_bb = (prod[b * p + b] - sum[b] * sum[b] / dn) / (dn - 1.0);
    const double signal = sum[b] / dn - sigma2 * cov.trace()[b], noise = sigma2 * cov.trace()[b];
    const double nu = dof(n, lo[b], hi[b]), d33c = (4.0 * signal * noise + 2.0 * noise * noise) / nu;
    INFO("band " << lo[b] << " .. " << hi[b] << " Hz: Monte-Carlo variance " << mc_bb << ", exact " << exact[b * p + b]
                 << ", D-33c b's locally white form " << d33c << " (" << d33c / mc_bb << " x)");
    CHECK(exact[b * p + b] == doctest::Approx(mc_bb).epsilon(0.08));
    CHECK(estimate[b * p + b] == doctest::Approx(exact[b * p + b]).epsilon(0.08));
    for (std::size_t e = 0; e < p; ++e) {
      const double mc = (prod[b * p + e] - sum[b] * sum[e] / dn) / (dn - 1.0);
      const double mc_ee = (prod[e * p + e] - sum[e] * sum[e] / dn) / (dn - 1.0), scale = std::sqrt(mc_bb * mc_ee);
      CHECK(exact[b * p + e] / scale == doctest::Approx(mc / scale).epsilon(0.0).scale(1.0).epsilon(0.05));
    }
  }
  // The two bands inside one bin move together (D-33c b leaves them independent).
  const double r01 = exact[1] / std::sqrt(exact[0] * exact[p + 1]);
  CHECK(r01 > 0.8);
}

TEST_CASE("bad input is refused") {
  const WelchConfig c = welch_config(100.0, 16, 8);
  CHECK_THROWS_AS(BandNoiseCovariance(c, 10, {1.0}, {5.0}), std::invalid_argument);       // shorter than L
  CHECK_THROWS_AS(BandNoiseCovariance(c, 64, {1.0, 2.0}, {5.0}), std::invalid_argument);  // edges unpaired
  CHECK_THROWS_AS(BandNoiseCovariance(c, 64, {70.0}, {80.0}), std::invalid_argument);     // above Nyquist
  const BandNoiseCovariance ok(c, 64, {1.0}, {30.0});
  const std::vector<double> x(64, 1.0);
  CHECK_THROWS_AS(ok.covariance(x.data(), {-1.0}), std::invalid_argument);
  CHECK_THROWS_AS(ok.covariance(x.data(), {1.0, 1.0}), std::invalid_argument);  // one per band
}
