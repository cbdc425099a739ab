// A fit's quadratic response surface (kernels/spectral D-27i) against its plain reference and exact
// quadratics, its lack-of-fit test's size and power, and the fitted combined test (D-27j): its size
// where the keys were fitted to the measurement, against the unfitted test's.
#include <doctest/doctest.h>

#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/band_test_table.hpp"
#include "philox_draws.hpp"
#include "sample_covariance.hpp"
#include "kernels/spectral/response_surface.hpp"

using namespace rollspec::spectral;

namespace {

// Standard normals from Philox keyed by (seed, stream), by Box-Muller.
struct Normals {
  std::uint64_t seed, stream, counter = 0;
  double operator()() {
    r123::Philox4x64 gen;
    const r123::Philox4x64::key_type key = {{seed, stream}};
    const r123::Philox4x64::ctr_type ctr = {{counter++, 0, 0, 0}};
    const auto r = gen(ctr, key);
    const double a = u01fixedpt_open_open_64_double(r[0]), b = u01fixedpt_open_open_64_double(r[1]);
    return std::sqrt(-2.0 * std::log(a)) * std::cos(2.0 * M_PI * b);
  }
};

DrawUniforms philox(std::uint64_t seed) {
  return [seed](std::uint64_t draw, double* u, std::size_t n) { testing::draw_uniforms(seed, draw, u, n); };
}

// A quadratic in two keys for band b: known value and gradient.
double quad(std::size_t b, double u0, double u1) {
  const double c = 0.1 * double(b);
  return 1.0 + c - 2.0 * u0 + (0.5 + c) * u1 + 3.0 * u0 * u0 - c * u0 * u1 + 0.7 * u1 * u1;
}

}  // namespace

TEST_CASE("D-27i: an exact quadratic is recovered, by QR as by the normal equations") {
  const std::size_t keys = 2, bands = 3;
  std::vector<double> u, y;
  for (const double a : {0.2, 0.3, 0.45, 0.5})
    for (const double b : {0.6, 0.7, 0.8}) {
      u.insert(u.end(), {a, b});
      for (std::size_t k = 0; k < bands; ++k) y.push_back(quad(k, a, b));
    }
  const std::vector<double> centre{0.35, 0.7}, half{0.15, 0.1};
  const ResponseSurface s = fit_response_surface(u, y, keys, bands, centre, half);
  const ResponseSurface r = fit_response_surface_reference(u, y, keys, bands, centre, half);
  CHECK(s.terms == 6);
  for (std::size_t i = 0; i < s.coefficients.size(); ++i)
    CHECK(s.coefficients[i] == doctest::Approx(r.coefficients[i]).epsilon(1e-10));
  for (std::size_t i = 0; i < s.gram_inverse.size(); ++i)
    CHECK(s.gram_inverse[i] == doctest::Approx(r.gram_inverse[i]).epsilon(1e-9).scale(1.0));
  const std::vector<double> at{0.33, 0.74};
  const std::vector<double> mu = s.value(at), g = s.gradient(at);
  for (std::size_t k = 0; k < bands; ++k) {
    const double c = 0.1 * double(k);
    CHECK(mu[k] == doctest::Approx(quad(k, at[0], at[1])).epsilon(1e-12));
    CHECK(g[k * keys + 0] == doctest::Approx(-2.0 + 6.0 * at[0] - c * at[1]).epsilon(1e-10));
    CHECK(g[k * keys + 1] == doctest::Approx(0.5 + c - c * at[0] + 1.4 * at[1]).epsilon(1e-10));
  }
  for (const double e : s.residuals) CHECK(std::fabs(e) < 1e-12);
  // The hat matrix's trace is the number of terms: the leverages of the runs sum to q.
  double trace = 0.0;
  for (std::size_t j = 0; j < s.runs; ++j) trace += s.leverage({u[2 * j], u[2 * j + 1]});
  CHECK(trace == doctest::Approx(6.0).epsilon(1e-10));
  // Too few runs, or a design that cannot tell the terms apart, is refused.
  CHECK_THROWS_AS(fit_response_surface({0.1, 0.2}, {1, 2}, 1, 1, {0.2}, {0.1}), std::invalid_argument);
  CHECK_THROWS_AS(
      fit_response_surface({0.1, 0.1, 0.1, 0.3, 0.3, 0.3}, std::vector<double>(6, 1.0), 2, 1, {0.2, 0.2}, {0.1, 0.1}),
      std::invalid_argument);
}

TEST_CASE("D-27i: the lack-of-fit statistic is chi-square when the quadratic holds, and sees a cubic") {
  const std::size_t bands = 4, runs = 9, trials = 3000;
  // Correlated run errors Omega (the bands of one run share its realisations).
  Eigen::MatrixXd omega(bands, bands);
  for (std::size_t a = 0; a < bands; ++a)
    for (std::size_t b = 0; b < bands; ++b) omega(a, b) = 0.01 * std::pow(0.5, std::fabs(double(a) - double(b)));
  const Eigen::MatrixXd l = omega.llt().matrixL();
  std::vector<double> om(bands * bands);
  for (std::size_t a = 0; a < bands; ++a)
    for (std::size_t b = 0; b < bands; ++b) om[a * bands + b] = omega(a, b);
  std::vector<double> u(runs);
  for (std::size_t j = 0; j < runs; ++j) u[j] = 0.3 + 0.4 * double(j) / double(runs - 1);
  std::size_t rejected = 0, cubic_rejected = 0;
  double mean_stat = 0.0;
  for (std::size_t t = 0; t < trials; ++t) {
    Normals z{17, t};
    std::vector<double> y(runs * bands), yc(runs * bands);
    for (std::size_t j = 0; j < runs; ++j) {
      Eigen::VectorXd e(bands);
      for (std::size_t b = 0; b < bands; ++b) e(b) = z();
      const Eigen::VectorXd le = l * e;
      const double x = (u[j] - 0.5) / 0.2;
      for (std::size_t b = 0; b < bands; ++b) {
        y[j * bands + b] = -1.0 + 0.3 * x - 0.2 * x * x + le(b);
        yc[j * bands + b] = y[j * bands + b] + 0.6 * x * x * x;  // a cubic the quadratic cannot follow
      }
    }
    const LackOfFit f = lack_of_fit(fit_response_surface(u, y, 1, bands, {0.5}, {0.2}), om);
    mean_stat += f.statistic / double(trials);
    rejected += f.p_value < 0.05;
    cubic_rejected += lack_of_fit(fit_response_surface(u, yc, 1, bands, {0.5}, {0.2}), om).p_value < 0.05;
    CHECK(f.dof == doctest::Approx(double(bands * (runs - 3))));
  }
  const double size = double(rejected) / double(trials), power = double(cubic_rejected) / double(trials);
  MESSAGE("lack of fit: mean R ", mean_stat, " (dof 24), size ", size, ", power against the cubic ", power);
  CHECK(mean_stat == doctest::Approx(24.0).epsilon(0.03));
  CHECK(size > 0.035);
  CHECK(size < 0.065);
  CHECK(power > 0.8);
}

// A key that moves the band logs along J: the measurement at the truth, the key fitted to it by GLS
// (minimising T^2), then tested. The projected test (D-27j) keeps its level; the unfitted test, blind to
// the fit having absorbed one direction of d, rejects less than its level says.
TEST_CASE("D-27j: the fitted test's size with the key fitted to the measurement") {
  const std::size_t p = 8, trials = 3000;
  const std::uint64_t K = 30;
  const double M = 25.0;
  Eigen::MatrixXd s_true(p, p);
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b)
      s_true(a, b) = 0.2 * (1.0 + 0.3 * std::sin(double(a))) * std::pow(0.3, std::fabs(double(a) - double(b)));
  s_true = 0.5 * (s_true + s_true.transpose());
  const Eigen::MatrixXd ls = s_true.llt().matrixL();
  std::vector<double> jac(p), mean0(p, 1e-3), st(p * p);
  for (std::size_t b = 0; b < p; ++b) jac[b] = -0.5 + 0.1 * double(b);
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b) st[a * p + b] = s_true(a, b);
  std::vector<double> d0, v0;
  std::vector<double> y0(p);
  for (std::size_t b = 0; b < p; ++b) y0[b] = std::log(mean0[b]);
  band_deviation(y0.data(), mean0.data(), st.data(), p, double(K), M, d0, v0);  // d0 = -offset
  const Eigen::MatrixXd lv =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(v0.data(), p, p)
          .llt()
          .matrixL();
  std::size_t fitted = 0, unfitted = 0;
  const TableTerm none{nullptr, 0.0, 0.0};
  for (std::size_t t = 0; t < trials; ++t) {
    Normals z{23, t};
    const Eigen::MatrixXd s_hat = testing::sample_covariance(ls, K - 1, z);
    std::vector<double> sh(p * p), y(p);
    for (std::size_t a = 0; a < p; ++a)
      for (std::size_t b = 0; b < p; ++b) sh[a * p + b] = s_hat(a, b);
    Eigen::VectorXd e(p);
    for (std::size_t b = 0; b < p; ++b) e(b) = z();
    const Eigen::VectorXd dev = lv * e;
    for (std::size_t b = 0; b < p; ++b) y[b] = y0[b] - d0[b] + dev(Eigen::Index(b));
    // GLS fit of the key theta (model band logs ln m0 + J theta) with V from the estimate S.
    std::vector<double> d, v;
    band_deviation(y.data(), mean0.data(), sh.data(), p, double(K), M, d, v);
    const Eigen::MatrixXd vm =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(v.data(), p, p);
    const Eigen::VectorXd jv = Eigen::Map<const Eigen::VectorXd>(jac.data(), p);
    const Eigen::VectorXd dv = Eigen::Map<const Eigen::VectorXd>(d.data(), p);
    const double theta = jv.dot(vm.llt().solve(dv)) / jv.dot(vm.llt().solve(jv));
    std::vector<double> mean(p);
    for (std::size_t b = 0; b < p; ++b) mean[b] = mean0[b] * std::exp(jac[b] * theta);
    fitted +=
        band_test_fitted(y.data(), mean.data(), sh.data(), p, K, M, jac.data(), 1, none, philox(1), 0).p_value < 0.05;
    unfitted += band_test(y.data(), mean.data(), sh.data(), p, K, M).p_value < 0.05;
  }
  const double size = double(fitted) / double(trials), size_unfitted = double(unfitted) / double(trials);
  MESSAGE("D-27j size ", size, ", unfitted ", size_unfitted);
  CHECK(size > 0.035);
  CHECK(size < 0.065);
  CHECK(size_unfitted < size);
}

TEST_CASE("D-27j: without fitted keys it is D-31's test; the projected T^2 ignores a move along J") {
  const std::size_t p = 5;
  std::vector<double> s(p * p, 0.0), mean(p, 1e-3), y(p), jac(p), moved(p);
  for (std::size_t b = 0; b < p; ++b) s[b * p + b] = 0.2 + 0.05 * double(b), jac[b] = 1.0 + 0.2 * double(b);
  for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) + 0.3 * std::cos(double(b));
  for (std::size_t b = 0; b < p; ++b) moved[b] = mean[b] * std::exp(0.4 * jac[b]);
  const TableTerm none{nullptr, 0.0, 0.0};
  const BandTestResult a =
      band_test_fitted(y.data(), mean.data(), s.data(), p, 30, 25.0, nullptr, 0, none, philox(1), 0);
  const BandTestResult b = band_test_with_table(y.data(), mean.data(), s.data(), p, 30, 25.0, none, philox(1), 0);
  CHECK(a.t2 == b.t2);
  CHECK(a.p_value == b.p_value);
  // Diagonal S: G S G is diagonal too and d moves by exactly 0.4 J, which the projection removes.
  const BandTestResult f =
      band_test_fitted(y.data(), mean.data(), s.data(), p, 30, 25.0, jac.data(), 1, none, philox(1), 0);
  const BandTestResult g =
      band_test_fitted(y.data(), moved.data(), s.data(), p, 30, 25.0, jac.data(), 1, none, philox(1), 0);
  CHECK(f.dof1 == 4.0);
  CHECK(f.dof2 == 29.0 - 4.0 + 1.0);
  CHECK(f.t2 == doctest::Approx(g.t2).epsilon(1e-10));
  CHECK(f.t2 < b.t2);
  CHECK_THROWS_AS(band_test_fitted(y.data(), mean.data(), s.data(), p, 30, 25.0, std::vector<double>(25, 1.0).data(), 5,
                                   none, philox(1), 0),
                  std::invalid_argument);
}

TEST_CASE("D-27a with a table term and a mean share: ln L of uncorrelated bands, band by band") {
  const std::size_t p = 3;
  const std::uint64_t K = 30;
  const double M = 10.0, h = 0.3, n = 200.0;
  const std::vector<double> cov{0.3, 0, 0, 0, 0.2, 0, 0, 0, 0.5}, mean{1e-3, 2e-3, 5e-4}, r{0.1, -0.2, 0.05};
  const std::vector<double> table{0.02, 0, 0, 0, 0.01, 0, 0, 0, 0.03};
  std::vector<double> y(p);
  double expected = 0.0;
  const double c = (n - 3.0) * (n - 4.0) / (n * (n - 1.0));
  for (std::size_t b = 0; b < p; ++b) {
    const double s = cov[b * p + b], vm = std::log1p(std::expm1(s) / M), vk = std::log1p(std::expm1(s) / 30.0);
    y[b] = std::log(mean[b]) + 0.5 * (vk - vm) + r[b];
    const double var = vm + h * vk + table[b * p + b];
    expected += -0.5 * c * (r[b] * r[b] / var + std::log(var));
  }
  const double got = band_log_likelihood(y.data(), mean.data(), cov.data(), p, K, M, {h, n, table.data()});
  CHECK(got == doctest::Approx(expected).epsilon(1e-12));
  CHECK(band_log_likelihood(y.data(), mean.data(), cov.data(), p, K, M, LikelihoodTerms{}) ==
        band_log_likelihood(y.data(), mean.data(), cov.data(), p, K, M));
}
