// Combined test over bands of a measurement against an ensemble (kernels/spectral D-26).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "kernels/spectral/band_test.hpp"

using namespace rollspec::spectral;

namespace {

// The sample covariance (divisor K - 1) of the K rows of logs about their mean lm, p x p row-major.
std::vector<double> log_covariance(const std::vector<std::vector<double>>& logs, const std::vector<double>& lm) {
  const std::size_t p = lm.size();
  std::vector<double> cov(p * p);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c) {
      double s = 0.0;
      for (const auto& l : logs) s += (l[b] - lm[b]) * (l[c] - lm[c]);
      cov[b * p + c] = s / static_cast<double>(logs.size() - 1);
    }
  return cov;
}

// A measurement: the mean of M draws (x is the draws' scratch).
template <class Draw>
std::vector<double> mean_of_draws(Draw& draw, std::vector<double>& x, double M) {
  std::vector<double> meas(x.size(), 0.0);
  for (int m = 0; m < static_cast<int>(M); ++m) {
    draw(x);
    for (std::size_t b = 0; b < x.size(); ++b) meas[b] += x[b] / M;
  }
  return meas;
}

}  // namespace

TEST_CASE("band test: a known diagonal case gives the F tail probability") {
  // p = 3 uncorrelated bands, K = 24 (nu = 23, F(3, 21)), M = 25; the deviation is set so that F = 2.5.
  const std::size_t p = 3;
  const std::uint64_t K = 24;
  const double M = 25.0, s = 0.3;
  const std::vector<double> cov{s, 0, 0, 0, s, 0, 0, 0, s}, mean{1e-3, 2e-3, 5e-4};
  const double vm = std::log1p(std::expm1(s) / M), vk = std::log1p(std::expm1(s) / K);
  const double t2 = 2.5 * 23.0 * 3.0 / 21.0, d = std::sqrt(t2 * (vm + vk) / 3.0);
  std::vector<double> y(p);
  for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) + 0.5 * (vk - vm) + (b == 1 ? -d : d);
  const BandTestResult r = band_test(y.data(), mean.data(), cov.data(), p, K, M);
  REQUIRE(r.defined);
  CHECK(r.t2 == doctest::Approx(t2).epsilon(1e-12));
  CHECK(r.f == doctest::Approx(2.5).epsilon(1e-12));
  CHECK(r.dof1 == 3.0);
  CHECK(r.dof2 == 21.0);
  // /usr/bin/python3 -c "from scipy import stats; print(repr(stats.f.sf(2.5, 3, 21)))"
  CHECK(r.p_value == doctest::Approx(0.08736945343994482).epsilon(1e-10));
}

TEST_CASE("band test: Cholesky form equals the plain inverse on a correlated covariance") {
  const std::size_t p = 5;
  std::vector<double> cov(p * p), mean(p), y(p);
  for (std::size_t b = 0; b < p; ++b) {
    mean[b] = std::pow(10.0, -3.0 - 0.2 * static_cast<double>(b));
    y[b] = std::log(mean[b]) + 0.1 * std::sin(1.0 + static_cast<double>(b));
    for (std::size_t c = 0; c < p; ++c)
      cov[b * p + c] = 0.4 * std::pow(0.7, std::fabs(static_cast<double>(b) - static_cast<double>(c)));
  }
  const BandTestResult r = band_test(y.data(), mean.data(), cov.data(), p, 40, 25.0);
  REQUIRE(r.defined);
  CHECK(r.t2 == doctest::Approx(band_test_t2_reference(y.data(), mean.data(), cov.data(), p, 40, 25.0)).epsilon(1e-12));
}

TEST_CASE("band test: too few realisations for the bands is refused with the count needed") {
  const std::size_t p = 6;
  std::vector<double> cov(p * p, 0.0), mean(p, 1.0), y(p, 0.0);
  for (std::size_t b = 0; b < p; ++b) cov[b * p + b] = 0.2;
  const BandTestResult r = band_test(y.data(), mean.data(), cov.data(), p, 9, 25.0);
  CHECK_FALSE(r.defined);
  CHECK(r.needed == p + kExtraRealisations);
  CHECK(band_test(y.data(), mean.data(), cov.data(), p, r.needed, 25.0).defined);
}

// Lognormal band values with correlated logs: a correct-model measurement (mean of M records) is
// rejected at about the nominal rate; one 3 dB too high in every band nearly always.
TEST_CASE("band test: size near nominal and power on simulated lognormal bands") {
  const std::size_t p = 6;
  const std::uint64_t K = 60;
  const double M = 25.0, sy = 0.6, rho = 0.6;
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> normal(0.0, 1.0);
  // x_b = exp(sy (sqrt(rho) z0 + sqrt(1 - rho) z_b) + mu_b): equicorrelated logs.
  auto draw = [&](std::vector<double>& x) {
    const double z0 = normal(rng);
    for (std::size_t b = 0; b < p; ++b)
      x[b] = std::exp(sy * (std::sqrt(rho) * z0 + std::sqrt(1.0 - rho) * normal(rng)) - 0.3 * static_cast<double>(b));
  };
  const int trials = 8000;  // binomial s.e. 0.0024 at 0.05
  int rejected = 0, rejected_shifted = 0;
  std::vector<double> x(p), mean(p), cov(p * p), ly(p), y(p), y_shift(p), meas(p);
  for (int t = 0; t < trials; ++t) {
    std::vector<std::vector<double>> logs;
    std::fill(mean.begin(), mean.end(), 0.0);
    for (std::uint64_t k = 0; k < K; ++k) {
      draw(x);
      for (std::size_t b = 0; b < p; ++b) mean[b] += x[b] / static_cast<double>(K), ly[b] = std::log(x[b]);
      logs.push_back(ly);
    }
    std::vector<double> lm(p, 0.0);
    for (const auto& l : logs)
      for (std::size_t b = 0; b < p; ++b) lm[b] += l[b] / static_cast<double>(K);
    cov = log_covariance(logs, lm);
    meas = mean_of_draws(draw, x, M);
    for (std::size_t b = 0; b < p; ++b) y[b] = std::log(meas[b]), y_shift[b] = y[b] + std::log(2.0);
    rejected += band_test(y.data(), mean.data(), cov.data(), p, K, M).p_value < 0.05;
    rejected_shifted += band_test(y_shift.data(), mean.data(), cov.data(), p, K, M).p_value < 0.05;
  }
  const double size = rejected / static_cast<double>(trials);
  CHECK(size > 0.03);
  CHECK(size < 0.075);
  CHECK(rejected_shifted / static_cast<double>(trials) > 0.9);
}

// Many bands for few realisations, wide spreads, weak correlation (as the seed 002 rig: p = 16, K = 30):
// the size stays nominal only if V is S scaled band by band (D-26a); the elementwise
// ln(1 + (e^S - 1)/n) of the noisy S rejected 0.005 here (T^2 too small: its inverse is not Wishart's).
TEST_CASE("band test: size near nominal with many bands, few realisations and wide spreads") {
  const std::size_t p = 12;
  const std::uint64_t K = 20;
  const double M = 25.0, rho = 0.1;
  std::mt19937_64 rng(2027);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto draw = [&](std::vector<double>& x) {
    const double z0 = normal(rng);
    for (std::size_t b = 0; b < p; ++b) {
      const double sy = 0.3 + 0.06 * static_cast<double>(b);  // log spreads 0.3 .. 0.96
      x[b] = std::exp(sy * (std::sqrt(rho) * z0 + std::sqrt(1.0 - rho) * normal(rng)) - 0.2 * static_cast<double>(b));
    }
  };
  const int trials = 3000;
  int rejected = 0;
  std::vector<double> x(p), mean(p), lm(p), cov(p * p), y(p), meas(p);
  std::vector<std::vector<double>> logs(K, std::vector<double>(p));
  for (int t = 0; t < trials; ++t) {
    std::fill(mean.begin(), mean.end(), 0.0);
    std::fill(lm.begin(), lm.end(), 0.0);
    for (auto& l : logs) {
      draw(x);
      for (std::size_t b = 0; b < p; ++b)
        mean[b] += x[b] / static_cast<double>(K), l[b] = std::log(x[b]), lm[b] += l[b] / static_cast<double>(K);
    }
    cov = log_covariance(logs, lm);
    meas = mean_of_draws(draw, x, M);
    for (std::size_t b = 0; b < p; ++b) y[b] = std::log(meas[b]);
    rejected += band_test(y.data(), mean.data(), cov.data(), p, K, M).p_value < 0.05;
  }
  const double size = rejected / static_cast<double>(trials);  // binomial s.e. 0.004 at 0.05
  CHECK(size > 0.035);
  CHECK(size < 0.07);
}
