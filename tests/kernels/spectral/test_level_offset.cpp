// One level offset over the compared bands (kernels/spectral D-34).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels/spectral/level_offset.hpp"

using namespace rollspec::spectral;

TEST_CASE("D-34: equal uncorrelated bands give the mean deviation and sigma^2 / p") {
  const std::size_t p = 4;
  const std::vector<double> d{1.0, 2.0, 3.0, 6.0};
  std::vector<double> v(p * p, 0.0);
  for (std::size_t b = 0; b < p; ++b) v[b * p + b] = 0.5;
  const LevelOffset o = level_offset(d.data(), v.data(), nullptr, p, 24.0, 1.0, 0.95);
  CHECK(o.estimate == doctest::Approx(3.0).epsilon(1e-14));
  CHECK(o.variance == doctest::Approx(0.5 / 4.0).epsilon(1e-14));
  CHECK(o.dof == doctest::Approx(24.0).epsilon(1e-14));
  // /usr/bin/python3 -c "from scipy import stats; print(stats.t.ppf(0.975, 24))"
  CHECK(o.upper - o.estimate == doctest::Approx(2.0638985616280205 * std::sqrt(0.125)).epsilon(1e-10));
}

TEST_CASE("D-34: the matrix form equals plain loops with a table term") {
  const std::size_t p = 6;
  std::vector<double> d(p), vs(p * p), vt(p * p);
  for (std::size_t b = 0; b < p; ++b) {
    d[b] = std::sin(1.0 + double(b));
    for (std::size_t c = 0; c < p; ++c) {
      vs[b * p + c] = 0.3 * std::pow(0.5, std::fabs(double(b) - double(c))) * (1.0 + 0.1 * double(b + c));
      vt[b * p + c] = 0.05 * std::cos(0.3 * double(b)) * std::cos(0.3 * double(c));  // rank one
    }
  }
  const LevelOffset a = level_offset(d.data(), vs.data(), vt.data(), p, 24.0, 5.0, 0.95);
  const LevelOffset r = level_offset_reference(d.data(), vs.data(), vt.data(), p, 24.0, 5.0, 0.95);
  CHECK(a.estimate == doctest::Approx(r.estimate).epsilon(1e-12));
  CHECK(a.variance == doctest::Approx(r.variance).epsilon(1e-12));
  CHECK(a.dof == doctest::Approx(r.dof).epsilon(1e-12));
  CHECK(a.dof > 5.0);
  CHECK(a.dof < 24.0 + 5.0);  // Welch-Satterthwaite: between the smaller dof and their sum
}

TEST_CASE("D-34: the weights follow the bands' own variances") {
  const std::size_t p = 2;
  const std::vector<double> d{1.0, 4.0}, v{1.0, 0.5, 0.5, 3.0};
  const LevelOffset o = level_offset(d.data(), v.data(), nullptr, p, 1e6, 1.0, 0.95);
  CHECK(o.estimate == doctest::Approx((1.0 / 1.0 * 1.0 + 1.0 / 3.0 * 4.0) / (1.0 + 1.0 / 3.0)).epsilon(1e-14));
  // var = w^T V w with w = (3/4, 1/4)
  CHECK(o.variance == doctest::Approx(0.75 * 0.75 * 1.0 + 2.0 * 0.75 * 0.25 * 0.5 + 0.25 * 0.25 * 3.0).epsilon(1e-14));
}

TEST_CASE("D-34: the interval covers a known offset at its level") {
  const std::size_t p = 5, trials = 4000;
  std::vector<double> v(p * p);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c) v[b * p + c] = 0.2 * std::pow(0.6, std::fabs(double(b) - double(c)));
  // Cholesky factor of v by hand (p = 5), for the draws.
  std::vector<double> l(p * p, 0.0);
  for (std::size_t j = 0; j < p; ++j)
    for (std::size_t i = j; i < p; ++i) {
      double s = v[i * p + j];
      for (std::size_t k = 0; k < j; ++k) s -= l[i * p + k] * l[j * p + k];
      l[i * p + j] = i == j ? std::sqrt(s) : s / l[j * p + j];
    }
  std::mt19937_64 gen(5);
  std::normal_distribution<double> z;
  std::size_t covered = 0;
  for (std::size_t t = 0; t < trials; ++t) {
    std::vector<double> e(p), d(p, -3.0);
    for (auto& x : e) x = z(gen);
    for (std::size_t i = 0; i < p; ++i)
      for (std::size_t k = 0; k <= i; ++k) d[i] += l[i * p + k] * e[k];
    const LevelOffset o = level_offset(d.data(), v.data(), nullptr, p, 1e6, 1.0, 0.95);
    covered += o.lower <= -3.0 && -3.0 <= o.upper;
  }
  CHECK(double(covered) / trials == doctest::Approx(0.95).epsilon(0.02));
}
