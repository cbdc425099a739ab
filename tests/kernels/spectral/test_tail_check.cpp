// Are K realisations enough for a band's interval? (kernels/spectral D-29.)
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "kernels/spectral/tail_check.hpp"
#include "philox_draws.hpp"

using namespace rollspec::spectral;

namespace {

using testing::PhiloxUniforms;

// One standard normal from two uniforms (Box-Muller's cosine branch).
double normal(PhiloxUniforms& u) { return std::sqrt(-2.0 * std::log(u.next())) * std::cos(2.0 * M_PI * u.next()); }

// The engine's path: raw power sums of y.
TailCheck from_sums(const std::vector<double>& y) {
  double s1 = 0.0, s2 = 0.0, s3 = 0.0;
  for (double v : y) s1 += v, s2 += v * v, s3 += v * v * v;
  return tail_check(y.size(), s1, s2, s3);
}

}  // namespace

TEST_CASE("one outlier among K: G1 = sqrt(K) exactly, and Cochran's K from G1 less two standard errors") {
  std::vector<double> y(25, -20.0);
  y[7] = -20.0 + 2.3;  // one realisation ten times the power of the rest
  const TailCheck t = tail_check_reference(y.data(), y.size());
  CHECK(t.defined);
  CHECK(t.skewness == doctest::Approx(5.0).epsilon(1e-12));
  const double se = std::sqrt(6.0 * 25 * 24 / (23.0 * 26 * 28));
  CHECK(t.standard_error == doctest::Approx(se).epsilon(1e-14));
  CHECK(t.needed == static_cast<std::uint64_t>(std::ceil(25.0 * (5.0 - 2.0 * se) * (5.0 - 2.0 * se))));
  CHECK_FALSE(t.enough(25));
  CHECK(t.enough(t.needed));
  // The raw sums lose little to the offset of the logs (-20, spread 0.46).
  const TailCheck s = from_sums(y);
  CHECK(s.skewness == doctest::Approx(t.skewness).epsilon(1e-8));
  CHECK(s.needed == t.needed);
}

TEST_CASE("symmetric and left-skewed logs ask for nothing; no scatter or K < 3 is undefined") {
  const std::vector<double> sym{-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0};
  CHECK(tail_check_reference(sym.data(), sym.size()).skewness == doctest::Approx(0.0).epsilon(1e-15));
  CHECK(from_sums(sym).needed == 0);
  std::vector<double> left(25, 1.0);
  left[3] = -5.0;  // one realisation without much power: a light right tail of x
  CHECK(from_sums(left).skewness == doctest::Approx(-5.0).epsilon(1e-10));
  CHECK(from_sums(left).needed == 0);
  CHECK_FALSE(from_sums(std::vector<double>(10, -7.5)).defined);
  CHECK_FALSE(from_sums({1.0, 2.0}).defined);
  CHECK(from_sums({1.0, 2.0}).enough(2));
}

TEST_CASE("raw sums agree with the two-pass reference on random logs") {
  PhiloxUniforms u(11);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> y(8 + static_cast<std::size_t>(trial) * 3);
    for (double& v : y) v = -15.0 + 0.8 * normal(u) + (u.next() < 0.1 ? 2.0 : 0.0);
    const TailCheck a = from_sums(y), b = tail_check_reference(y.data(), y.size());
    CHECK(a.skewness == doctest::Approx(b.skewness).epsilon(1e-8).scale(1.0));
    CHECK(a.standard_error == b.standard_error);
  }
}

// Simulated (D-29 table): lognormal band values (normal logs) rarely warn at K = 25; a mixture in
// which 10 % of the realisations carry 10 times the power (D-21's under-covered case) mostly does.
TEST_CASE("warning rates: lognormal realisations against a 10 % x 10 mixture, K = 25") {
  PhiloxUniforms u(2026);
  const int trials = 2000, K = 25;
  int warn_normal = 0, warn_mixture = 0;
  std::vector<double> y(K), z(K);
  for (int t = 0; t < trials; ++t) {
    for (int k = 0; k < K; ++k) {
      y[static_cast<std::size_t>(k)] = 1.5 * normal(u);
      // Gamma(20) band values (a sum of 20 exponentials) times 10 with probability 0.1.
      double g = 0.0;
      for (int i = 0; i < 20; ++i) g -= std::log(u.next());
      z[static_cast<std::size_t>(k)] = std::log(g / 20.0) + (u.next() < 0.1 ? std::log(10.0) : 0.0);
    }
    warn_normal += !from_sums(y).enough(K);
    warn_mixture += !from_sums(z).enough(K);
  }
  CHECK(warn_normal < trials / 100);      // simulated 0.001 (D-29)
  CHECK(warn_mixture > trials * 6 / 10);  // simulated 0.69 (D-29)
}
