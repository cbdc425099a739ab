// Shrinking a table's covariance toward its diagonal (kernels/spectral D-31e): Schaefer-Strimmer's intensity by
// hand, against its plain reference, its invariances, and what it does with independent and with common errors.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "kernels/spectral/covariance_shrinkage.hpp"
#include "philox_draws.hpp"

using namespace rollspec::spectral;

namespace {

// n units of p bands: `common` times one normal shared by every band plus an own normal per band.
std::vector<double> units(std::size_t n, std::size_t p, double common, std::uint64_t seed) {
  testing::PhiloxNormals z(seed);
  std::vector<double> x(n * p);
  for (std::size_t i = 0; i < n; ++i) {
    const double c = common * z.next();
    for (std::size_t k = 0; k < p; ++k) x[i * p + k] = c + z.next();
  }
  return x;
}

}  // namespace

TEST_CASE("D-31e b: two identical bands over three units, by hand: lambda = 1/4") {
  // z = (-1, 0, 1) for both: w = (1, 0, 1), r = 3/2 * 2/3 = 1, Var^(r) = 3/8 * (1/9 + 4/9 + 1/9) = 1/4.
  const std::vector<double> x = {-1.0, 5.0, 0.0, 7.0, 1.0, 9.0};  // band 2 = 2 band 1 + 7: the same correlations
  CHECK(shrinkage_intensity(x.data(), 3, 2) == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(shrinkage_intensity_reference(x.data(), 3, 2) == doctest::Approx(0.25).epsilon(1e-14));
}

TEST_CASE("D-31e b: the matrix form equals the pair-by-pair reference, a constant band left out") {
  for (const std::size_t n : {3u, 6u, 10u})
    for (const std::size_t p : {2u, 5u, 18u}) {
      std::vector<double> x = units(n, p, 0.7, 100 * n + p);
      for (std::size_t i = 0; i < n; ++i) x[i * p + p / 2] = -41.5;  // a band that does not vary
      const double fast = shrinkage_intensity(x.data(), n, p), ref = shrinkage_intensity_reference(x.data(), n, p);
      CHECK(fast == doctest::Approx(ref).epsilon(1e-12));
      CHECK(fast >= 0.0);
      CHECK(fast <= 1.0);
    }
  const std::vector<double> one = {1.0, 2.0, 3.0};
  CHECK(shrinkage_intensity(one.data(), 3, 1) == 1.0);  // no pair of bands
  std::vector<double> bad = units(4, 3, 0.0, 7);
  bad[4] = NAN;
  CHECK_THROWS_AS(shrinkage_intensity(bad.data(), 4, 3), std::invalid_argument);
}

TEST_CASE("D-31e b: a band's scale and offset (dB or natural log, any level) leave lambda as it is") {
  const std::size_t n = 6, p = 12;
  const std::vector<double> x = units(n, p, 1.0, 31);
  std::vector<double> y = x;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < p; ++k) y[i * p + k] = (3.0 + double(k)) * x[i * p + k] - 40.0 + double(k);
  CHECK(shrinkage_intensity(y.data(), n, p) == doctest::Approx(shrinkage_intensity(x.data(), n, p)).epsilon(1e-10));
}

TEST_CASE("D-31e: the more the bands' errors go together, the less they shrink") {
  // Six units (a beam S table) of 18 bands, a common part c times each band's own (correlation c^2 / (1 + c^2)).
  // With none every sample correlation is noise: lambda* near 1; as the common part grows the correlations
  // stand above their noise and lambda* falls, but not to 0: Var^(r) estimates the scatter of the products of
  // standardised values, which at n = 6 stays about a quarter of r^2 even when the bands move as one (the
  // hand case above: 1/4 at n = 3).
  const std::size_t n = 6, p = 18, trials = 50;
  std::vector<double> mean;
  for (const double c : {0.0, 1.0, 3.0, 10.0}) {
    double m = 0.0;
    for (std::size_t t = 0; t < trials; ++t)
      m += shrinkage_intensity(units(n, p, c, 500 + 100 * mean.size() + t).data(), n, p) / double(trials);
    MESSAGE("common part ", c, ": mean lambda* ", m);
    mean.push_back(m);
  }
  CHECK(mean[0] > 0.7);
  for (std::size_t i = 1; i < mean.size(); ++i) CHECK(mean[i] < mean[i - 1]);
  CHECK(mean.back() < 0.5 * mean[0]);
}

TEST_CASE("D-31e a: the diagonal kept, every correlation scaled by 1 - lambda") {
  std::vector<double> c = {4.0, 1.0, -2.0, 1.0, 9.0, 0.5, -2.0, 0.5, 1.0};
  shrink_toward_diagonal(c.data(), 3, 0.25);
  const std::vector<double> want = {4.0, 0.75, -1.5, 0.75, 9.0, 0.375, -1.5, 0.375, 1.0};
  for (std::size_t i = 0; i < c.size(); ++i) CHECK(c[i] == want[i]);
}
