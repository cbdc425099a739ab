// D-33c b, c: logger noise in a measured band. Closed forms (white signal plus white noise is white), the moments
// of Monte-Carlo rolls of a signal plus noise through WelchPlan and band_average, and the terms D-26's deviation
// takes from them.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/band_noise.hpp"
#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "philox_draws.hpp"
#include "welch_config.hpp"

using namespace rollspec::spectral;
using rollspec::spectral::testing::welch_config;

namespace {

using Normals = testing::PhiloxNormals;

}  // namespace

TEST_CASE("white signal plus white noise is white: the noise's share of the variance is 2 (1 - a^2) / nu") {
  // X = P_s + P_n + C of white S and N is the band average of white S + N: relative variance 2 / nu in all. The
  // signal alone has 2 / nu, entering times a^2; the rest is the noise's and the cross term's.
  for (const double nu : {3.0, 7.67, 40.0, 1473.0})
    for (const double r : {1e-6, 0.05, 0.25, 1.0, 9.0}) {
      const BandNoise n = band_noise(2.0, 2.0 * r, nu, 10.0 * nu);
      const double a = 1.0 / (1.0 + r), one_less_a = r / (1.0 + r);  // 1 - a without cancellation
      CHECK(n.signal_share * 2.0 / nu + std::expm1(n.measured) == doctest::Approx(2.0 / nu).epsilon(1e-13).scale(0.0));
      CHECK(std::expm1(n.estimate) ==
            doctest::Approx(2.0 * one_less_a * one_less_a / (10.0 * nu)).epsilon(1e-13).scale(0.0));
      CHECK(n.shift == doctest::Approx(std::log1p(r)).epsilon(1e-15).scale(0.0));
      CHECK(n.signal_share == doctest::Approx(a * a).epsilon(1e-15).scale(0.0));
    }
  const BandNoise none = band_noise(3.0, 0.0, 10.0, 10.0);
  CHECK(none.shift == 0.0);
  CHECK(none.signal_share == 1.0);
  CHECK(none.measured == 0.0);
  CHECK(none.estimate == 0.0);
  const BandNoise unknown = band_noise(3.0, 1.0, 0.0, 0.0);  // dof unknown: the shift alone
  CHECK(unknown.shift == doctest::Approx(std::log(4.0 / 3.0)).epsilon(1e-15).scale(0.0));
  CHECK(unknown.measured == 0.0);
  CHECK(unknown.estimate == 0.0);
  CHECK_THROWS_AS(band_noise(0.0, 1.0, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(band_noise(1.0, -1.0, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(band_noise(1.0, 1.0, -1.0, 1.0), std::invalid_argument);
}

TEST_CASE("Monte-Carlo: M rolls of signal plus noise have mean m + N and the variance D-33c gives") {
  // Each roll: a white signal whose level varies between rolls (g^2 lognormal, E g^2 = 1, log sd 0.1) plus white
  // noise at a quarter of its power (a = 0.8). Exact moments of one roll's band: E X = S + N; var X = var P_s +
  // (2 N^2 + 4 S N) / nu_b, var P_s = S^2 (e^{0.01} (1 + 2 / nu_b) - 1). 12 000 trials of M = 4 rolls: the sample
  // variance's relative standard error is about 1.4 %, the tolerance 5 %; a cross term of 2 S N / nu_b would
  // give 13 % less, the signal's variance without a^2 39 % more.
  const WelchConfig c = welch_config(1000.0, 64, 32);
  const WelchPlan plan(c);
  WelchWorkspace ws(c.segment);
  const double df = plan.frequency_step(), lo = 6.3 * df, hi = 14.1 * df;
  const std::size_t n = 256, rolls = 4, trials = 12000;
  const double S = 2.0 / c.sample_rate, noise_sd = 0.5, N = S * noise_sd * noise_sd, log_sd = 0.1;
  const double nu = BandDof(c)(n, lo, hi);
  const BandNoise terms = band_noise(S, N, static_cast<double>(rolls) * nu, 0.0);
  const double cv2 = std::exp(log_sd * log_sd) * (1.0 + 2.0 / nu) - 1.0;  // one roll's signal, relative
  const double predicted = terms.signal_share * cv2 / static_cast<double>(rolls) + std::expm1(terms.measured);

  Normals normal(2024);
  std::vector<double> x(n), p(plan.n_freq());
  double sum = 0.0, sq = 0.0;
  for (std::size_t t = 0; t < trials; ++t) {
    double mean = 0.0;
    for (std::size_t r = 0; r < rolls; ++r) {
      const double g = std::exp(0.5 * (log_sd * normal.next() - 0.5 * log_sd * log_sd));
      for (double& v : x) v = g * normal.next() + noise_sd * normal.next();
      plan.psd(x.data(), n, p.data(), ws);
      mean += band_average(p.data(), p.size(), df, lo, hi) / static_cast<double>(rolls);
    }
    sum += mean;
    sq += mean * mean;
  }
  const double m = sum / trials, var = (sq - trials * m * m) / (trials - 1.0);
  INFO("nu_b " << nu << ", predicted relative variance " << predicted << ", measured " << var / ((S + N) * (S + N)));
  CHECK(m == doctest::Approx(S * std::exp(terms.shift)).epsilon(4.0 * std::sqrt(var / trials) / m).scale(0.0));
  CHECK(var / ((S + N) * (S + N)) == doctest::Approx(predicted).epsilon(0.05).scale(0.0));
}

TEST_CASE("D-26's terms with noise: none is D-26 bit for bit; else a^2 on the signal, the noise on the diagonal") {
  const std::size_t p = 3;
  const std::vector<double> y = {0.1, -0.4, 2.0}, mean = {1.2, 0.5, 6.0};
  const std::vector<double> s = {0.04, 0.01, 0.0, 0.01, 0.09, 0.02, 0.0, 0.02, 0.25};
  const double K = 40.0, M = 5.0;
  std::vector<double> d0, v0, d1, v1, d2, v2;
  band_deviation(y.data(), mean.data(), s.data(), p, K, M, d0, v0);
  const std::vector<BandNoise> zero(p);
  band_deviation(y.data(), mean.data(), s.data(), p, K, M, d1, v1, zero.data());
  CHECK(d1 == d0);  // bit for bit
  CHECK(v1 == v0);
  const std::vector<BandNoise> noise = {band_noise(1.2, 0.1, 50.0, 400.0), band_noise(0.5, 0.0, 50.0, 400.0),
                                        band_noise(6.0, 1.5, 20.0, 100.0)};
  band_deviation(y.data(), mean.data(), s.data(), p, K, M, d2, v2, noise.data());
  for (std::size_t b = 0; b < p; ++b) {
    const double vm = std::log(1.0 + std::expm1(s[b * p + b]) / M), vk = std::log(1.0 + std::expm1(s[b * p + b]) / K);
    const BandNoise& n = noise[b];
    const double a2 = n.signal_share;
    CHECK(d2[b] == doctest::Approx(y[b] -
                                   std::log(mean[b] * (1.0 + (b == 1   ? 0.0
                                                              : b == 0 ? 0.1 / 1.2
                                                                       : 0.25))) -
                                   0.5 * (a2 * vk + n.estimate - a2 * vm - n.measured))
                       .epsilon(1e-14)
                       .scale(0.0));
    for (std::size_t c = 0; c < p; ++c) {
      const double ac = noise[c].signal_share;
      const double want = std::sqrt(a2 * ac) * v0[b * p + c] + (b == c ? n.measured + n.estimate : 0.0);
      CHECK(std::fabs(v2[b * p + c] - want) <= 1e-14 * std::fabs(want));
    }
  }
}
