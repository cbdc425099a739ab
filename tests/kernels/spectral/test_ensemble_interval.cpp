// Intervals of an ensemble mean from the realisations' scatter (kernels/spectral D-21, D-22).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/ensemble_interval.hpp"
#include "philox_draws.hpp"

using namespace rollspec::spectral;

namespace {

// Gamma(shape, 1/shape) variates (mean 1, CV 1/sqrt(shape)) for integer shape: a sum of exponentials.
class GammaDraws {
 public:
  GammaDraws(int shape, std::uint64_t key) : shape_(shape), uniform_(key) {}
  double normal() {  // Box-Muller
    return std::sqrt(-2.0 * std::log(uniform_.next())) * std::cos(2.0 * M_PI * uniform_.next());
  }
  double next() {
    double s = 0.0;
    for (int i = 0; i < shape_; ++i) s -= std::log(uniform_.next());
    return s / shape_;
  }

 private:
  int shape_;
  testing::PhiloxUniforms uniform_;
};

// Moments of n draws of x and of ln x, as the engine accumulates them.
Scatter draw(GammaDraws& g, int n, bool lognormal = false) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& xi : x) xi = lognormal ? std::exp(g.normal() * 1.5 - 1.125) : g.next();  // ln N(-s^2/2, s = 1.5): mean 1
  Scatter s;
  for (double xi : x) s.mean += xi, s.log_mean += std::log(xi);
  s.mean /= n;
  s.log_mean /= n;
  for (double xi : x) {
    s.std_dev += (xi - s.mean) * (xi - s.mean);
    s.log_std += (std::log(xi) - s.log_mean) * (std::log(xi) - s.log_mean);
  }
  s.std_dev = std::sqrt(s.std_dev / (n - 1));
  s.log_std = std::sqrt(s.log_std / (n - 1));
  return s;
}

}  // namespace

constexpr double kNoLog = std::numeric_limits<double>::quiet_NaN();  // the gamma law alone

TEST_CASE("D-21a: exponential realisations (one periodogram each), K = 25: chi-square on 50 dof, widened by t_24/z") {
  // scipy: (50 / chi2.ppf(0.975, 50))^w, (50 / chi2.ppf(0.025, 50))^w, w = t.ppf(0.975, 24) / norm.ppf(0.975)
  const auto i = mean_interval({2.0, 2.0, 0.0, kNoLog}, 25, 0.95);
  CHECK(i.dof == doctest::Approx(50.0));
  CHECK(i.lower == doctest::Approx(0.6869694186236697).epsilon(1e-9));
  CHECK(i.upper == doctest::Approx(1.5813177838067582).epsilon(1e-9));
}

TEST_CASE("D-21a: large K tends to the chi-square interval of the Satterthwaite dof") {
  const auto i = mean_interval({1.0, 10.0, 0.0, kNoLog}, 5000, 0.95);  // nu = 2 * 5000 / 100 = 100
  const auto c = chi_square_interval(100.0, 0.95);
  CHECK(i.dof == doctest::Approx(100.0));
  CHECK(std::log(i.lower) == doctest::Approx(std::log(c.lower)).epsilon(2e-3));
  CHECK(std::log(i.upper) == doctest::Approx(std::log(c.upper)).epsilon(2e-3));
}

TEST_CASE("D-21b and the union: Cox's lognormal interval, K = 16, widens the gamma-law one where it is wider") {
  // scipy: c = -0.3 + 0.5 - ln 1.2, h = t.ppf(0.975, 15) sqrt(1/16 + 1/30): exp(c -/+ h)
  const auto i = mean_interval({1.2, 1.2, -0.3, 1.0}, 16, 0.95);
  CHECK(i.lower == doctest::Approx(0.5261581076266194).epsilon(1e-9));
  CHECK(i.upper == doctest::Approx(1.9689697038692566).epsilon(1e-9));
  // The gamma law alone (nu = 32): (32 / chi2.ppf(0.975, 32))^w, (32 / chi2.ppf(0.025, 32))^w, w = t_15 / z
  const auto g = mean_interval({1.2, 1.2, -0.3, kNoLog}, 16, 0.95);
  CHECK(g.lower == doctest::Approx(0.6225227457156937).epsilon(1e-9));
  CHECK(g.upper == doctest::Approx(1.837266034218778).epsilon(1e-9));
  // A narrow log spread leaves the gamma-law interval as it is.
  const auto n = mean_interval({1.2, 1.2, std::log(1.2) - 0.005, 0.1}, 16, 0.95);
  CHECK(n.lower == g.lower);
  CHECK(n.upper == g.upper);
}

TEST_CASE("D-22: prediction of a 25-record mean from K = 10 exponential realisations: F(50, 20), widened by t_9/z") {
  // scipy: f.ppf(0.025, 50, 20)^w, f.ppf(0.975, 50, 20)^w, w = t.ppf(0.975, 9) / norm.ppf(0.975)
  const auto p = prediction_interval({3.0, 3.0, 0.0, kNoLog}, 10, 25.0, 0.95);
  CHECK(p.dof == doctest::Approx(20.0));
  CHECK(p.lower == doctest::Approx(0.4510655907711577).epsilon(1e-9));
  CHECK(p.upper == doctest::Approx(2.5487404144102337).epsilon(1e-9));
  // D-22b, K = 16, M = 25, s_y = 1: CV^2 = e - 1, v_M = ln(1 + CV^2/25), v_K = ln(1 + CV^2/16),
  // exp((v_K - v_M)/2 -/+ t_15 sqrt(v_M + v_K))
  const auto q = prediction_interval({1.2, 1.2, -0.3, 1.0}, 16, 25.0, 0.95);
  CHECK(q.lower == doctest::Approx(0.4243847884294874).epsilon(1e-9));
  CHECK(q.upper == doctest::Approx(2.4415931399983255).epsilon(1e-9));
}

TEST_CASE("edge cases: too few realisations, no scatter, no power, a zero value, bad arguments") {
  const auto few = mean_interval({1.0, 0.5, 0.0, 0.4}, kMinRealisationsForInterval - 1, 0.95);
  CHECK_FALSE(few.defined());
  CHECK(few.lower == 0.0);
  CHECK(std::isinf(few.upper));
  CHECK_FALSE(prediction_interval({1.0, 0.5, 0.0, 0.4}, 4, 25.0, 0.95).defined());
  const auto fixed = mean_interval({1.0, 0.0, 0.0, 0.0}, 10, 0.95);  // deterministic value: the mean is exact
  CHECK(fixed.lower == 1.0);
  CHECK(fixed.upper == 1.0);
  const auto zero = mean_interval({0.0, 0.0, -HUGE_VAL, kNoLog}, 10, 0.95);
  CHECK(zero.lower == 1.0);
  CHECK(zero.upper == 1.0);
  // One realisation with no power: ln x = -inf, so only the gamma law is used.
  const auto some = mean_interval({1.0, 1.0, -HUGE_VAL, kNoLog}, 20, 0.95);
  const auto gamma = mean_interval({1.0, 1.0, 0.0, kNoLog}, 20, 0.95);
  CHECK(some.lower == gamma.lower);
  CHECK(some.upper == gamma.upper);
  CHECK_THROWS(mean_interval({1.0, 1.0, 0.0, 0.5}, 10, 1.0));
  CHECK_THROWS(mean_interval({1.0, 1.0, 0.0, 0.5}, 0, 0.95));
  CHECK_THROWS(prediction_interval({1.0, 1.0, 0.0, 0.5}, 10, 0.5, 0.95));
}

TEST_CASE("coverage by experiment: 4000 ensembles hold the true mean in 93-98 % (nominal 95 %)") {
  // Gamma realisations (Welch averages of 1 to 20 periodograms) and lognormal ones with s = 1.5
  // (power varying over orders of magnitude, as with intermittent contact); "measured" means of
  // M = 25 further records for the prediction interval. Expected from the laws' union: 0.94-0.98.
  struct Case {
    int shape, K;
    bool lognormal;
  };
  for (const auto& c : {Case{1, 5, false}, Case{3, 10, false}, Case{20, 8, false}, Case{3, 25, false},
                        Case{0, 16, true}, Case{0, 25, true}}) {
    CAPTURE(c.shape);
    CAPTURE(c.K);
    CAPTURE(c.lognormal);
    GammaDraws g(std::max(c.shape, 1), 1000u + static_cast<std::uint64_t>(c.shape * 100 + c.K) + (c.lognormal ? 7 : 0));
    const int trials = 4000, M = 25;
    int held = 0, predicted = 0;
    for (int t = 0; t < trials; ++t) {
      const auto e = draw(g, c.K, c.lognormal);
      const auto i = mean_interval(e, static_cast<std::uint64_t>(c.K), 0.95);
      held += (e.mean * i.lower <= 1.0 && 1.0 <= e.mean * i.upper);
      const double future = draw(g, M, c.lognormal).mean;
      const auto p = prediction_interval(e, static_cast<std::uint64_t>(c.K), M, 0.95);
      predicted += (e.mean * p.lower <= future && future <= e.mean * p.upper);
    }
    CHECK(held / double(trials) >= 0.93);
    CHECK(held / double(trials) <= 0.98);
    CHECK(predicted / double(trials) >= 0.93);
    CHECK(predicted / double(trials) <= 0.98);
  }
}

TEST_CASE("edge cases: a spread of many means (a damaged file, a vanishing signal) gives [0, inf), not an error") {
  // nu = 2 K (m / s)^2 far below 1: the gamma law's quantiles are 0 and beyond any double; boost's
  // series for them do not converge (or refuse a zero dof), which must not end the command.
  for (const double s : {1e3, 1e6, 1e300}) {
    CAPTURE(s);
    const auto m = mean_interval({1.0, s, 0.0, kNoLog}, 25, 0.95);
    CHECK(m.lower == 0.0);
    CHECK(std::isinf(m.upper));
    const auto p = prediction_interval({1e-10, s, 0.0, kNoLog}, 25, 5.0, 0.95);
    CHECK(p.lower == 0.0);
    CHECK(std::isinf(p.upper));
  }
  // Just above the floor the gamma law still gives a finite, wide interval.
  const auto wide = mean_interval({1.0, 60.0, 0.0, kNoLog}, 25, 0.95);  // nu = 50 / 3600 = 0.0139
  CHECK(wide.lower >= 0.0);
  CHECK(wide.upper > 1e6);
}
