// The combined test with a table term (kernels/spectral D-31): its limits, its bootstrap against the
// F law where that law is exact, and its size on simulated measurements from other tables.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/band_test_table.hpp"
#include "kernels/spectral/covariance_shrinkage.hpp"
#include "philox_draws.hpp"
#include "sample_covariance.hpp"

using namespace rollspec::spectral;

namespace {

// Philox uniforms keyed by (seed, draw), as the engine hands the kernel (philox_draws.hpp).
DrawUniforms philox(std::uint64_t seed) {
  return [seed](std::uint64_t draw, double* u, std::size_t n) { testing::draw_uniforms(seed, draw, u, n); };
}

Eigen::MatrixXd banded(std::size_t p, double level, double rho) {
  Eigen::MatrixXd s(p, p);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c)
      s(b, c) =
          level * (1.0 + 0.3 * std::sin(static_cast<double>(b))) * std::pow(rho, std::fabs(double(b) - double(c)));
  return 0.5 * (s + s.transpose());
}

std::vector<double> flat(const Eigen::MatrixXd& m) {
  std::vector<double> v(static_cast<std::size_t>(m.size()));
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) v[static_cast<std::size_t>(i * m.cols() + j)] = m(i, j);
  return v;
}

// Standard normals by Box-Muller pairs over one trial's uniforms, in order.
class BoxMuller {
 public:
  explicit BoxMuller(const std::vector<double>& u) : u_(u) {}
  double operator()() {
    const double a = u_[k_], b = u_[k_ + 1];
    k_ += 2;
    return std::sqrt(-2.0 * std::log(a)) * std::cos(2.0 * M_PI * b);
  }

 private:
  const std::vector<double>& u_;
  std::size_t k_ = 0;
};

// A model's table covariance from its N units (the columns: the table is their mean), the jackknife of D-30a.
Eigen::MatrixXd jackknife(const Eigen::MatrixXd& units) {
  const double n = double(units.cols());
  const Eigen::VectorXd ubar = units.rowwise().mean();
  const Eigen::MatrixXd dev = units.colwise() - ubar;
  return dev * dev.transpose() / (n * (n - 1.0));
}

// A measurement from another table: log mean - d + L_V e, with d and V D-26a's deviation and covariance at the true
// S for K realisations of M averages, plus twice `table` (the model's table and the measurement's each deviate from
// the roughness's mean by that covariance); e standard normal from z.
template <class Normal>
std::vector<double> measurement(const Eigen::MatrixXd& s_true, const Eigen::MatrixXd& table,
                                const std::vector<double>& mean, std::uint64_t K, double M, Normal&& z) {
  const std::size_t p = mean.size();
  std::vector<double> d, v;
  const auto st = flat(s_true);
  std::vector<double> y0(p);
  for (std::size_t b = 0; b < p; ++b) y0[b] = std::log(mean[b]);
  band_deviation(y0.data(), mean.data(), st.data(), p, double(K), M, d, v);  // d = -offset here
  const Eigen::MatrixXd v_true =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          v.data(), Eigen::Index(p), Eigen::Index(p)) +
      2.0 * table;
  const Eigen::MatrixXd lv = v_true.llt().matrixL();
  Eigen::VectorXd e(p);
  for (std::size_t b = 0; b < p; ++b) e(b) = z();
  const Eigen::VectorXd dev_y = lv * e;
  std::vector<double> y(p);
  for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) - d[b] + dev_y(Eigen::Index(b));
  return y;
}

}  // namespace

TEST_CASE("D-31: without a table term it is D-26's F test, bit for bit") {
  const std::size_t p = 5;
  const auto s = flat(banded(p, 0.3, 0.5));
  std::vector<double> mean(p, 1e-3), y(p);
  for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) + 0.2 * std::cos(double(b));
  const std::vector<double> zero(p * p, 0.0);
  const BandTestResult f = band_test(y.data(), mean.data(), s.data(), p, 30, 25.0);
  for (const TableTerm t : {TableTerm{zero.data(), 5.0, 2.0}, TableTerm{s.data(), 5.0, 0.0}}) {
    const BandTestResult r = band_test_with_table(y.data(), mean.data(), s.data(), p, 30, 25.0, t, philox(1), 100);
    CHECK(r.draws == 0);
    CHECK(r.t2 == f.t2);
    CHECK(r.p_value == f.p_value);
  }
}

TEST_CASE("D-31: with a negligible table term the bootstrap reproduces Hotelling's F law") {
  // T^2 with a Wishart estimate of its covariance is pivotal: the bootstrap about any S has the F law,
  // up to the noise of D-26a's band scaling G, which small log variances make negligible.
  const std::size_t p = 6;
  const Eigen::MatrixXd sm = banded(p, 0.01, 0.6);
  const auto s = flat(sm), tiny = flat(1e-9 * sm);
  std::vector<double> mean(p, 2e-4);
  const std::size_t draws = 20000;
  for (const double shift : {0.05, 0.12, 0.2}) {
    std::vector<double> y(p);
    for (std::size_t b = 0; b < p; ++b) y[b] = std::log(mean[b]) + 0.2 * shift * (b % 2 ? 1.0 : -0.7);
    const BandTestResult f = band_test(y.data(), mean.data(), s.data(), p, 25, 25.0);
    const BandTestResult r =
        band_test_with_table(y.data(), mean.data(), s.data(), p, 25, 25.0, {tiny.data(), 9.0, 2.0}, philox(7), draws);
    REQUIRE(r.draws == draws);
    CHECK(r.t2 == doctest::Approx(f.t2).epsilon(1e-6));
    const double se = std::sqrt(f.p_value * (1.0 - f.p_value) / double(draws));
    CHECK(std::fabs(r.p_value - f.p_value) < 4.0 * se + 1.0 / double(draws));
  }
}

TEST_CASE("D-31: Bartlett's decomposition has the Wishart's mean and the chi-square diagonal's variance") {
  const std::size_t q = 3, n = 20000;
  const double nu = 4.5;
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  double sq00 = 0.0;
  const DrawUniforms u = philox(3);
  std::vector<double> uni(bartlett_uniforms(q)), a(q * q);
  for (std::size_t j = 0; j < n; ++j) {
    u(j, uni.data(), uni.size());
    bartlett_wishart(q, nu, uni.data(), a.data());
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> m(a.data());
    sum += m;
    sq00 += m(0, 0) * m(0, 0);
  }
  const Eigen::Matrix3d mean = sum / double(n);
  CHECK((mean - nu * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 0.1);                  // E W(I, nu) = nu I
  CHECK(sq00 / double(n) - mean(0, 0) * mean(0, 0) == doctest::Approx(2.0 * nu).epsilon(0.05));  // chi2(nu)
}

// Measurements from another table: the model's table and the measurement's each deviate from the
// roughness's mean by N(0, Sigma_T); the model's Sigma_T is a jackknife of N units (Wishart, N - 1
// dof), its S a covariance of K realisations. The F test that leaves the table out rejects far too
// often; D-31 keeps its level.
TEST_CASE("D-31: size on simulated measurements from other tables" * doctest::test_suite("long")) {
  const std::size_t p = 8, N = 6, trials = 500, draws = 200;
  const std::uint64_t K = 25;
  const double M = 25.0;
  const Eigen::MatrixXd s_true = banded(p, 0.25, 0.3);
  // A table term of rank 3 (three shapes of the table's curve), comparable to the realisations' term.
  Eigen::MatrixXd shape(p, 3);
  for (std::size_t b = 0; b < p; ++b)
    shape.row(b) << 0.08, 0.05 * std::cos(0.7 * double(b)), 0.03 * std::sin(1.3 * double(b));
  const Eigen::MatrixXd t_true = shape * shape.transpose();
  const Eigen::MatrixXd ls = s_true.llt().matrixL(), lt = shape;
  std::vector<double> mean(p, 1e-3);
  const DrawUniforms sim = philox(99);
  std::size_t rejected = 0, rejected_f = 0;
  std::vector<double> uni(2 * (p * (K - 1) + 3 * N + p));
  for (std::size_t trial = 0; trial < trials; ++trial) {
    sim(trial, uni.data(), uni.size());
    BoxMuller z(uni);
    const Eigen::MatrixXd s_hat = testing::sample_covariance(ls, K - 1, z);
    Eigen::MatrixXd units(p, N);
    for (std::size_t i = 0; i < N; ++i) {
      Eigen::Vector3d e(z(), z(), z());
      units.col(i) = std::sqrt(double(N)) * (lt * e);  // the table is the mean of N such units
    }
    const Eigen::MatrixXd t_hat = jackknife(units);
    // The two tables' deviations and the measurement's and the ensemble's own scatter, in the
    // truth's V (D-26a with the true S).
    const std::vector<double> y = measurement(s_true, t_true, mean, K, M, z);
    const auto sh = flat(s_hat), th = flat(t_hat);
    const BandTestResult r = band_test_with_table(y.data(), mean.data(), sh.data(), p, K, M,
                                                  {th.data(), double(N - 1), 2.0}, philox(1000 + trial), draws);
    rejected += r.p_value < 0.05;
    rejected_f += band_test(y.data(), mean.data(), sh.data(), p, K, M).p_value < 0.05;
  }
  const double size = double(rejected) / trials, size_f = double(rejected_f) / trials;
  MESSAGE("D-31 size ", size, ", the F test without the table term ", size_f);
  CHECK(size > 0.02);
  CHECK(size < 0.08);
  CHECK(size_f > 0.15);
}

// Independent bands (D-31c): a spectral table's error, each band's variance from a jackknife of N_B
// Welch segments, nu_T dof apiece; the measurement from another table. The rank-limited jackknife
// covariance of the same draws leaves most directions without a table term and rejects far too often.
TEST_CASE("D-31c: size with independent bands, against the rank-limited covariance" * doctest::test_suite("long")) {
  const std::size_t p = 8, N = 5, trials = 400, draws = 200;
  const std::uint64_t K = 25;
  const double M = 25.0;
  const Eigen::MatrixXd s_true = banded(p, 0.2, 0.3), ls = s_true.llt().matrixL();
  Eigen::VectorXd sig(p);
  for (std::size_t b = 0; b < p; ++b) sig(b) = 0.05 * (1.0 + 0.5 * std::cos(double(b)));  // table variances
  const std::vector<double> mean(p, 1e-3);
  const Eigen::MatrixXd t_true = sig.asDiagonal();
  const DrawUniforms sim = philox(4242);
  std::size_t rejected = 0, rejected_full = 0;
  std::vector<double> uni(2 * (p * (K - 1) + p * N + p));
  for (std::size_t trial = 0; trial < trials; ++trial) {
    sim(trial, uni.data(), uni.size());
    BoxMuller z(uni);
    const Eigen::MatrixXd s_hat = testing::sample_covariance(ls, K - 1, z);
    Eigen::MatrixXd units(p, N);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t b = 0; b < p; ++b) units(b, i) = std::sqrt(double(N) * sig(b)) * z();
    const Eigen::MatrixXd t_hat = jackknife(units);
    const std::vector<double> y = measurement(s_true, t_true, mean, K, M, z);
    const auto sh = flat(s_hat), th = flat(t_hat);
    rejected += band_test_with_table(y.data(), mean.data(), sh.data(), p, K, M, {th.data(), double(N - 1), 2.0, true},
                                     philox(5000 + trial), draws)
                    .p_value < 0.05;
    rejected_full += band_test_with_table(y.data(), mean.data(), sh.data(), p, K, M,
                                          {th.data(), double(N - 1), 2.0, false}, philox(5000 + trial), draws)
                         .p_value < 0.05;
  }
  const double size = double(rejected) / trials, size_full = double(rejected_full) / trials;
  MESSAGE("D-31c size ", size, ", with the rank-limited covariance ", size_full);
  CHECK(size > 0.02);
  CHECK(size < 0.08);
  CHECK(size_full > 0.12);
}

TEST_CASE("D-31d: neighbouring bands' variances pooled, the ends with fewer") {
  std::vector<std::size_t> count;
  const std::vector<double> v = smoothed_variances({3.0, 6.0, 0.0, 9.0}, 1, &count);
  CHECK(v == std::vector<double>{4.5, 3.0, 5.0, 4.5});
  CHECK(count == std::vector<std::size_t>{2, 3, 3, 2});
  CHECK(smoothed_variances({1.0, 2.0}, 0) == std::vector<double>{1.0, 2.0});
}

// D-31e: a stiffness-like table over N = 6 units of p = 16 bands: one shape every band shares (a stiffer table
// lifts them all) and an own part per band (full rank). The rank-5 jackknife leaves 11 directions without
// the own part's term and rejects too often; shrunk toward its diagonal by Schaefer-Strimmer's lambda* the test
// holds its level.
TEST_CASE("D-31e: size with a common and an own table error, raw and shrunk" * doctest::test_suite("long")) {
  const std::size_t p = 16, N = 6, trials = 300, draws = 200;
  const std::uint64_t K = 40;
  const double M = 25.0;
  const Eigen::MatrixXd s_true = banded(p, 0.1, 0.3), ls = s_true.llt().matrixL();
  Eigen::VectorXd common(p), own(p);
  for (std::size_t b = 0; b < p; ++b)
    common(b) = 0.12 * (1.0 + 0.4 * std::sin(0.5 * double(b))), own(b) = 0.08 * (1.0 + 0.3 * std::cos(double(b)));
  const Eigen::MatrixXd t_true =
      common * common.transpose() + Eigen::MatrixXd(own.array().square().matrix().asDiagonal());
  const std::vector<double> mean(p, 1e-3);
  testing::PhiloxNormals z(777);
  std::size_t rejected_raw = 0, rejected_shrunk = 0;
  double lambda_mean = 0.0;
  for (std::size_t trial = 0; trial < trials; ++trial) {
    const Eigen::MatrixXd s_hat = testing::sample_covariance(ls, K - 1, [&] { return z.next(); });
    Eigen::MatrixXd units(p, N);
    for (std::size_t i = 0; i < N; ++i) {
      const double c = z.next();
      for (std::size_t b = 0; b < p; ++b)
        units(b, i) = std::sqrt(double(N)) * (common(b) * c + own(b) * z.next());  // the table: the mean of N
    }
    const Eigen::MatrixXd t_hat = jackknife(units);
    // units is p x N column-major: unit i's p bands are contiguous, as shrinkage_intensity reads them.
    const double lambda = shrinkage_intensity(units.data(), N, p);
    lambda_mean += lambda / trials;
    const std::vector<double> y = measurement(s_true, t_true, mean, K, M, [&] { return z.next(); });
    const auto sh = flat(s_hat), th = flat(t_hat);
    rejected_raw += band_test_with_table(y.data(), mean.data(), sh.data(), p, K, M, {th.data(), double(N - 1), 2.0},
                                         philox(7000 + trial), draws)
                        .p_value < 0.05;
    rejected_shrunk +=
        band_test_with_table(y.data(), mean.data(), sh.data(), p, K, M,
                             {th.data(), double(N - 1), 2.0, false, 0, lambda}, philox(7000 + trial), draws)
            .p_value < 0.05;
  }
  const double raw = double(rejected_raw) / trials, shrunk = double(rejected_shrunk) / trials;
  MESSAGE("D-31e size raw ", raw, ", shrunk ", shrunk, " (mean lambda* ", lambda_mean, ")");
  CHECK(raw > 0.12);
  CHECK(shrunk > 0.02);
  CHECK(shrunk < 0.08);
}
