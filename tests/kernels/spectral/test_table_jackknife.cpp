// The table's own error by a leave-one-surface-out jackknife (kernels/spectral D-30).
#include <doctest/doctest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "kernels/spectral/table_jackknife.hpp"

using namespace rollspec::spectral;

namespace {
double t975(double dof) { return boost::math::quantile(boost::math::students_t(dof), 0.975); }
}  // namespace

TEST_CASE("jackknife variance: two passes equal the pairwise reference") {
  const std::vector<double> theta = {-41.3, -40.9, -42.2, -41.0, -41.75, -40.2, -41.1, -41.4, -43.0, -40.6};
  const double v = jackknife_variance(theta.data(), theta.size());
  CHECK(v == doctest::Approx(jackknife_variance_reference(theta.data(), theta.size())).epsilon(1e-13));
  CHECK(jackknife_variance(theta.data(), 1) == 0.0);
  std::vector<double> bad = theta;
  bad[3] = -std::numeric_limits<double>::infinity();  // a bin without power in one run
  CHECK(std::isnan(jackknife_variance(bad.data(), bad.size())));
}

TEST_CASE("jackknife of a mean is the sample variance of the mean, s^2 / N") {
  // theta_i: the mean without value i. The jackknife reproduces the textbook variance exactly.
  const std::vector<double> x = {3.1, 2.4, 5.0, 4.2, 3.3, 2.9, 4.8, 3.7};
  const double n = static_cast<double>(x.size());
  double sum = 0.0;
  for (double v : x) sum += v;
  std::vector<double> theta;
  double ss = 0.0;
  for (double v : x) {
    theta.push_back((sum - v) / (n - 1.0));
    ss += (v - sum / n) * (v - sum / n);
  }
  CHECK(jackknife_variance(theta.data(), theta.size()) == doctest::Approx(ss / (n - 1.0) / n).epsilon(1e-12));
}

TEST_CASE("widened half width: Welch-Satterthwaite between its limits") {
  const std::uint64_t K = 25;
  const double N1 = 9.0;  // table dof: N - 1 over N = 10 surfaces
  const double h = 0.4;   // dB
  // No table term: the interval is left alone.
  const auto none = widen_half_width(h, K, 0.0, N1, 0.95);
  CHECK(none.half_width == h);
  CHECK(none.dof == 24.0);
  CHECK(widen_half_width(h, K, std::nan(""), N1, 0.95).half_width == h);
  CHECK(widen_half_width(HUGE_VAL, K, 0.1, N1, 0.95).half_width == HUGE_VAL);  // no interval stays none
  // A value worked by hand: s_w = h / t_24, s^2 = s_w^2 + v, nu = s^4 / (s_w^4/24 + v^2/9).
  const double v = 0.09, s_w = h / t975(24.0), s2 = s_w * s_w + v;
  const double nu = s2 * s2 / (std::pow(s_w, 4) / 24.0 + v * v / 9.0);
  const auto w = widen_half_width(h, K, v, N1, 0.95);
  CHECK(w.dof == doctest::Approx(nu).epsilon(1e-14));
  CHECK(w.half_width == doctest::Approx(t975(nu) * std::sqrt(s2)).epsilon(1e-14));
  CHECK(w.half_width > h);
  // A negligible realisation term: the table's alone, t_{N-1} sqrt(v).
  const auto table_only = widen_half_width(1e-9, K, v, N1, 0.95);
  CHECK(table_only.dof == doctest::Approx(9.0).epsilon(1e-9));
  CHECK(table_only.half_width == doctest::Approx(t975(9.0) * std::sqrt(v)).epsilon(1e-9));
}

TEST_CASE("paired noise: the sums' form equals the plain reference") {
  std::mt19937_64 rng(30);
  std::gamma_distribution<double> power(2.0, 1.5);  // PSD-like positive values
  const std::size_t n = 6;
  const std::uint64_t K = 17;
  std::vector<double> x(n * K), m(n, 0.0);
  double q = 0.0;
  for (std::uint64_t r = 0; r < K; ++r) {
    const double shared = power(rng);
    double xr = 0.0;
    for (std::size_t i = 0; i < n; ++i) xr += (x[i * K + r] = shared + 0.1 * static_cast<double>(i) + power(rng));
    xr /= static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) q += (x[i * K + r] - xr) * (x[i * K + r] - xr);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint64_t r = 0; r < K; ++r) m[i] += x[i * K + r];
    m[i] /= static_cast<double>(K);
  }
  const double ref = paired_noise_variance_reference(x.data(), n, K);
  CHECK(ref > 0.0);
  CHECK(paired_noise_variance(q, m.data(), n, K) == doctest::Approx(ref).epsilon(1e-12));
  CHECK(std::isnan(paired_noise_variance(q, m.data(), n, 1)));
}

TEST_CASE("paired noise: without a table effect it is what the jackknife measures, on average") {
  // Runs that differ only by their own noise (a shared part, as common random numbers leave, plus
  // an independent part): E[V_J] equals E[noise], so (c) leaves no table variance on average.
  std::mt19937_64 rng(31);
  std::gamma_distribution<double> shared_power(4.0, 1.0), own(1.0, 0.5);
  const std::size_t n = 10;
  const std::uint64_t K = 25;
  double vj = 0.0, noise = 0.0;
  const int trials = 4000;
  std::vector<double> x(n * K), m(n), theta(n);
  for (int t = 0; t < trials; ++t) {
    double q = 0.0;
    for (std::uint64_t r = 0; r < K; ++r) {
      const double a = shared_power(rng);
      double xr = 0.0;
      for (std::size_t i = 0; i < n; ++i) xr += (x[i * K + r] = a + own(rng));
      xr /= static_cast<double>(n);
      for (std::size_t i = 0; i < n; ++i) q += (x[i * K + r] - xr) * (x[i * K + r] - xr);
    }
    for (std::size_t i = 0; i < n; ++i) {
      m[i] = 0.0;
      for (std::uint64_t r = 0; r < K; ++r) m[i] += x[i * K + r];
      m[i] /= static_cast<double>(K);
      theta[i] = 10.0 * std::log10(m[i]);
    }
    vj += jackknife_variance(theta.data(), n);
    noise += paired_noise_variance(q, m.data(), n, K);
  }
  // 4000 trials of a 9-dof variance: the ratio's standard error is about 0.4 %.
  CHECK(vj / noise == doctest::Approx(1.0).epsilon(0.02));
}
