// The fit's search on the unit box (kernels/spectral D-27) against a dense grid and analytic answers.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/fit_search.hpp"

using namespace rollspec::spectral;

namespace {

// A correlated quadratic bowl with its minimum at c (a negative log-likelihood of a Gaussian).
double bowl(const std::vector<double>& x, const std::vector<double>& c) {
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - c[i];
    s += 40.0 * (static_cast<double>(i) + 1.0) * d * d;
    if (i > 0) s += 30.0 * d * (x[i - 1] - c[i - 1]);
  }
  return s;
}

}  // namespace

TEST_CASE("fit search: the simplex finds the grid's minimum of smooth functions in 1 to 3 dimensions") {
  for (std::size_t n = 1; n <= 3; ++n) {
    const std::vector<double> c{0.37, 0.61, 0.22};
    const std::vector<double> centre(c.begin(), c.begin() + static_cast<long>(n));
    const BoxObjective f = [&](const std::vector<double>& x) { return bowl(x, centre) + std::sin(3.0 * x[0]); };
    const BoxMinimum grid = box_minimum_grid_reference(f, n, n == 3 ? 61 : 401);
    const BoxMinimum nm = box_minimum(f, std::vector<double>(n, 0.5), 0.2, 1e-9, 2000);
    CHECK(nm.value <= grid.value + 1e-12);  // at least as good as the grid
    const double spacing = 1.0 / (n == 3 ? 60.0 : 400.0);
    for (std::size_t i = 0; i < n; ++i) CHECK(std::fabs(nm.x[i] - grid.x[i]) <= spacing);
    CHECK(nm.evaluations < 2000);
  }
}

TEST_CASE("fit search: a minimum beyond the box is found on its edge, as by the grid") {
  const BoxObjective f = [](const std::vector<double>& x) {
    return (x[0] + 0.3) * (x[0] + 0.3) + (x[1] - 0.5) * (x[1] - 0.5);
  };
  const BoxMinimum nm = box_minimum(f, {0.5, 0.5}, 0.25, 1e-10, 1000);
  const BoxMinimum grid = box_minimum_grid_reference(f, 2, 101);
  CHECK(grid.x[0] == 0.0);
  CHECK(std::fabs(nm.x[0]) < 1e-6);
  CHECK(std::fabs(nm.x[1] - 0.5) < 1e-4);
}

TEST_CASE("fit search: the profile interval of a Gaussian log-likelihood is its 1.96-sigma interval") {
  const double mu = 0.4, sigma = 0.05, rise = 3.84 / 2.0;
  int evaluations = 0;
  const auto profile = [&](double t) { return 0.5 * (t - mu) * (t - mu) / (sigma * sigma); };
  const double lo = profile_end(profile, mu, 0.0, 0.0, rise, 1e-9, &evaluations);
  const double hi = profile_end(profile, mu, 0.0, 1.0, rise, 1e-9, &evaluations);
  CHECK(lo == doctest::Approx(mu - std::sqrt(3.84) * sigma).epsilon(1e-7));
  CHECK(hi == doctest::Approx(mu + std::sqrt(3.84) * sigma).epsilon(1e-7));
  // A flat profile reaches both ends.
  const auto flat = [](double) { return 1.0; };
  CHECK(profile_end(flat, mu, 1.0, 0.0, rise, 1e-9, &evaluations) == 0.0);
  CHECK(profile_end(flat, mu, 1.0, 1.0, rise, 1e-9, &evaluations) == 1.0);
}

TEST_CASE("fit search: the profile continues from the nearest solved point, not from the range's end") {
  // A ridge y = t whose profile is ((t - 0.5)/0.1)^2, and a basin at y = 0.02 of height 30 beside it: a
  // profile search started from the range end's optimum (y near 0) falls into the basin near t = 0.5.
  const BoxObjective f = [](const std::vector<double>& x) {
    const double ridge = std::pow((x[1] - x[0]) / 0.05, 2) + std::pow((x[0] - 0.5) / 0.1, 2);
    const double basin = 30.0 + std::pow((x[1] - 0.02) / 0.01, 2);
    return std::min(ridge, basin);
  };
  const double rise = 3.84 / 2.0, end = 0.1 * std::sqrt(rise);
  int evaluations = 0;
  ProfileContinuation profile(f, 2, 0, 0.5, {0.5}, 0.05, 1e-4, 40);
  const double lo = profile_end(std::ref(profile), 0.5, 0.0, 0.0, rise, 1e-4, &evaluations);
  const double hi = profile_end(std::ref(profile), 0.5, 0.0, 1.0, rise, 1e-4, &evaluations);
  CHECK(lo == doctest::Approx(0.5 - end).epsilon(2e-3));
  CHECK(hi == doctest::Approx(0.5 + end).epsilon(2e-3));
  // The start carried over from the previous call (the former rule) collapses the lower end onto 0.5.
  std::vector<double> others{0.5};
  const auto carried = [&](double t) {
    const BoxObjective g = [&](const std::vector<double>& o) { return f({t, o[0]}); };
    const BoxMinimum m = box_minimum(g, others, 0.05, 1e-4, 40);
    others = m.x;
    return m.value;
  };
  CHECK(profile_end(carried, 0.5, 0.0, 0.0, rise, 1e-4, &evaluations) > 0.5 - 0.5 * end);
}

TEST_CASE("fit search: Hessian and correlation of a bivariate Gaussian's negative log-likelihood") {
  // -ln L = x^T A x / 2 with A the inverse of the covariance [[s1^2, r s1 s2], [r s1 s2, s2^2]].
  const double s1 = 0.1, s2 = 0.2, r = -0.6, det = s1 * s1 * s2 * s2 * (1 - r * r);
  const std::vector<double> a{s2 * s2 / det, -r * s1 * s2 / det, -r * s1 * s2 / det, s1 * s1 / det};
  const BoxObjective f = [&](const std::vector<double>& x) {
    const double u = x[0] - 0.5, v = x[1] - 0.02;  // near an edge: the stencil moves inside
    return 0.5 * (a[0] * u * u + 2.0 * a[1] * u * v + a[3] * v * v);
  };
  int evaluations = 0;
  const std::vector<double> h = box_hessian(f, {0.5, 0.02}, 0.05, &evaluations);
  for (std::size_t i = 0; i < 4; ++i) CHECK(h[i] == doctest::Approx(a[i]).epsilon(1e-9));
  const std::vector<double> corr = inverse_correlation(h, 2);
  REQUIRE(corr.size() == 4);
  CHECK(corr[1] == doctest::Approx(r).epsilon(1e-9));
  CHECK(corr[0] == doctest::Approx(1.0));
  CHECK(inverse_correlation({1.0, 2.0, 2.0, 1.0}, 2).empty());  // not positive definite
}

TEST_CASE("fit likelihood: ln L of uncorrelated bands is the sum of the bands' Gaussian terms") {
  const std::size_t p = 3;
  const std::uint64_t K = 30;
  const double M = 10.0;
  const std::vector<double> cov{0.3, 0, 0, 0, 0.2, 0, 0, 0, 0.5}, mean{1e-3, 2e-3, 5e-4}, r{0.1, -0.2, 0.05};
  std::vector<double> y(p);
  double expected = 0.0;
  for (std::size_t b = 0; b < p; ++b) {
    const double s = cov[b * p + b], vm = std::log1p(std::expm1(s) / M), vk = std::log1p(std::expm1(s) / 30.0);
    y[b] = std::log(mean[b]) + 0.5 * (vk - vm) + r[b];
    const double c = 26.0 * 25.0 / (29.0 * 28.0);  // (n - p)(n - p - 1) / (n (n - 1)), n = K - 1 = 29, p = 3
    expected += -0.5 * c * (r[b] * r[b] / (vm + vk) + std::log(vm + vk));
  }
  CHECK(band_log_likelihood(y.data(), mean.data(), cov.data(), p, K, M) == doctest::Approx(expected).epsilon(1e-12));
}

TEST_CASE("fit search: Fisher's combination of p-values against chi-square tail values") {
  // One test: its own p. Two tests of p = 0.05 each: x = -2 ln 0.0025 = 11.98, P(chi2_4 >= x) = 0.0174787.
  CHECK(fisher_combined_p({0.3}) == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(fisher_combined_p({0.05, 0.05}) == doctest::Approx(0.0174787).epsilon(1e-5));
  // Three: x = -2 ln(0.5 * 0.2 * 0.9) = 4.8159; P(chi2_6 >= x) = exp(-x/2)(1 + x/2 + (x/2)^2/2) = 0.567634.
  const double h = -std::log(0.5 * 0.2 * 0.9);
  CHECK(fisher_combined_p({0.5, 0.2, 0.9}) == doctest::Approx(std::exp(-h) * (1.0 + h + h * h / 2.0)).epsilon(1e-14));
  CHECK(fisher_combined_p({0.5, 0.2, 0.9}) == doctest::Approx(0.567634).epsilon(1e-5));
  CHECK(fisher_combined_p({1.0, 1.0}) == 1.0);
  CHECK(fisher_combined_p({0.4, 0.0}) == 0.0);
  CHECK(fisher_combined_p({}) == 1.0);
}
