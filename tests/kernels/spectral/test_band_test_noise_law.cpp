// The law of T^2 with the logger noise's terms (kernels/spectral D-31b, D-33f): the noise's terms of V are known
// far better than S, so where they dominate a direction of V, T^2 there is nearly chi^2 and Hotelling's F law
// (S's estimation error in all p directions) is conservative. The bootstrap with the noise's terms held at their
// estimates draws the law as it is.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernels/spectral/band_noise.hpp"
#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/band_test_table.hpp"
#include "philox_draws.hpp"
#include "sample_covariance.hpp"

using namespace rollspec::spectral;

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

DrawUniforms philox(std::uint64_t seed) {
  return [seed](std::uint64_t draw, double* u, std::size_t n) { testing::draw_uniforms(seed, draw, u, n); };
}

// p bands, the first `noisy` of them with a logger noise 1 / share^2 ... times the signal's part of V: a^2 = 0.04,
// the measured mean's noise log variance 0.25 and the quiet recording's 0.002 (a long quiet recording: its terms
// nearly exact). The others without noise.
std::vector<BandNoise> noise_terms(std::size_t p, std::size_t noisy) {
  std::vector<BandNoise> n(p);
  for (std::size_t b = 0; b < noisy; ++b) n[b] = BandNoise{std::log(25.0 / 24.0), 0.04, 0.25, 0.002};
  return n;
}

// S of one realisation's band logs: level 0.05, correlation 0.4^|b - c|.
RowMatrix signal_covariance(std::size_t p) {
  RowMatrix s(p, p);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c) s(b, c) = 0.05 * std::pow(0.4, std::fabs(double(b) - double(c)));
  return s;
}

}  // namespace

TEST_CASE("D-33f: noise terms that are all zero leave the F law; any noise gives the bootstrap, same T^2") {
  const std::size_t p = 4;
  const RowMatrix s = signal_covariance(p);
  std::vector<double> mean(p, 1e-3), y(p);
  for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) + 0.1 * std::cos(double(b));
  const std::vector<BandNoise> none(p), some = noise_terms(p, 2);
  const TableTerm no_table{nullptr, 0.0, 0.0};
  const BandTestResult f0 = band_test(y.data(), mean.data(), s.data(), p, 20, 5.0, none.data());
  const BandTestResult r0 =
      band_test_with_table(y.data(), mean.data(), s.data(), p, 20, 5.0, no_table, philox(1), 500, none.data());
  CHECK(r0.draws == 0);  // bit for bit the F test
  CHECK(r0.t2 == f0.t2);
  CHECK(r0.p_value == f0.p_value);
  const BandTestResult f = band_test(y.data(), mean.data(), s.data(), p, 20, 5.0, some.data());
  const BandTestResult r =
      band_test_with_table(y.data(), mean.data(), s.data(), p, 20, 5.0, no_table, philox(1), 500, some.data());
  CHECK(r.draws == 500);
  CHECK(r.t2 == doctest::Approx(f.t2).epsilon(1e-12));
  const BandTestResult again =
      band_test_with_table(y.data(), mean.data(), s.data(), p, 20, 5.0, no_table, philox(1), 500, some.data());
  CHECK(again.p_value == r.p_value);  // the draws are keyed by their index: the same bits every time
}

// Measurements drawn from D-33c's own model: S^ a Wishart estimate of S (K - 1 dof), the measured band logs
// Gaussian about the model's with V = G S G + the noise's terms (the true S in G). Three of six bands are
// noise-dominated (their noise term 500 times the signal's): T^2 there is nearly chi^2_3, and the F law's
// critical value (Hotelling, p = 6, nu = 19) is well above what the statistic reaches: its size falls far below
// the level. 1000 trials: the size's Monte-Carlo standard error at 0.05 is 0.007.
TEST_CASE("D-33f: with noise-dominated bands the F law is conservative, the bootstrap holds the level") {
  const std::size_t p = 6, noisy = 3, trials = 1000, draws = 200;
  const std::uint64_t K = 20;
  const double M = 5.0, level = 0.05;
  const RowMatrix s_true = signal_covariance(p);
  const Eigen::MatrixXd ls = Eigen::MatrixXd(s_true).llt().matrixL();
  const std::vector<BandNoise> noise = noise_terms(p, noisy);
  const std::vector<double> mean(p, 1e-3);
  std::vector<double> y0(p), d0, v0;
  for (std::size_t b = 0; b < p; ++b) y0[b] = std::log(mean[b]);
  band_deviation(y0.data(), mean.data(), s_true.data(), p, double(K), M, d0, v0, noise.data());  // d0 = -offset
  const Eigen::MatrixXd lv = Eigen::MatrixXd(Eigen::Map<const RowMatrix>(v0.data(), p, p)).llt().matrixL();
  testing::PhiloxNormals z(20261130);
  std::size_t rejected_f = 0, rejected_b = 0;
  for (std::size_t trial = 0; trial < trials; ++trial) {
    const RowMatrix s_hat = testing::sample_covariance(ls, K - 1, [&] { return z.next(); });
    Eigen::VectorXd e(p);
    for (std::size_t b = 0; b < p; ++b) e(Eigen::Index(b)) = z.next();
    const Eigen::VectorXd dev = lv * e;
    std::vector<double> y(p);
    for (std::size_t b = 0; b < p; ++b) y[b] = y0[b] - d0[b] + dev(Eigen::Index(b));
    rejected_f += band_test(y.data(), mean.data(), s_hat.data(), p, K, M, noise.data()).p_value < level;
    rejected_b += band_test_with_table(y.data(), mean.data(), s_hat.data(), p, K, M, {nullptr, 0.0, 0.0},
                                       philox(1000 + trial), draws, noise.data())
                      .p_value < level;
  }
  const double size_f = double(rejected_f) / trials, size_b = double(rejected_b) / trials;
  const double se = std::sqrt(level * (1.0 - level) / trials);
  MESSAGE("D-33f size: F law ", size_f, ", bootstrap with the noise's terms held ", size_b, " (MC se ", se, ")");
  CHECK(size_f < level - 3.0 * se);             // conservative: it cannot reach its level
  CHECK(std::fabs(size_b - level) < 3.0 * se);  // the bootstrap's size within Monte-Carlo error of the level
}
