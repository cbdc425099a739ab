// Warm-started sweep along increasing approach (README Eq. 12), and the Hertz stiffness.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/sweep.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;
using rollspec::contact::test::WavyPlasticBall;

TEST_CASE("sweep equals cold solves (rough, elastic-plastic)") {
  WavyPlasticBall ball(12.0, 1.6);
  auto& [h, grid, gap, solver, opt] = ball;
  std::vector<double> approaches;
  for (int j = 0; j <= 10; ++j) approaches.push_back(-0.2 * h.approach + 0.12 * h.approach * j);
  std::vector<double> last;
  const auto results = sweep(solver, gap, approaches, opt, &last);
  REQUIRE(results.size() == approaches.size());
  CHECK(all_converged(results));
  CHECK(results.front().force == 0.0);  // −0.2 w0 lies below the first asperity
  int warm_iterations = 0, cold_iterations = 0;
  for (std::size_t j = 0; j < approaches.size(); ++j) {
    std::vector<double> p;
    const ContactResult cold = solver.solve(gap, approaches[j], p, opt);
    REQUIRE(cold.converged);
    CHECK(results[j].force == doctest::Approx(cold.force).epsilon(1e-8));
    CHECK(results[j].approach == approaches[j]);
    if (j > 0) CHECK(results[j].force >= results[j - 1].force);
    warm_iterations += results[j].iterations;
    cold_iterations += cold.iterations;
  }
  // On this small rough case the warm start saves nothing (measured: warm 158, cold 151
  // iterations); the saving shows on the smooth ball below.
  MESSAGE("rough sweep iterations: warm " << warm_iterations << ", cold " << cold_iterations);
  CHECK(last.size() == grid.size());
  CHECK_THROWS_AS(sweep(solver, gap, {1e-7, 1e-7}, opt), std::invalid_argument);
}

TEST_CASE("sweep warm start saves iterations on a smooth ball") {
  const Hertz h;
  const Grid grid = h.grid(12.0, 1.6);
  const auto gap = ball_gap(grid, h.radius, {});
  ContactSolver solver(grid, h.e_star);
  std::vector<double> approaches;
  for (int j = 0; j <= 10; ++j) approaches.push_back(0.1 * h.approach + 0.12 * h.approach * j);
  const auto results = sweep(solver, gap, approaches);
  REQUIRE(all_converged(results));
  int warm_iterations = 0, cold_iterations = 0;
  for (std::size_t j = 0; j < approaches.size(); ++j) {
    std::vector<double> p;
    const ContactResult cold = solver.solve(gap, approaches[j], p);
    REQUIRE(cold.converged);
    CHECK(results[j].force == doctest::Approx(cold.force).epsilon(1e-8));
    warm_iterations += results[j].iterations;
    cold_iterations += cold.iterations;
  }
  MESSAGE("smooth sweep iterations: warm " << warm_iterations << ", cold " << cold_iterations);
  CHECK(warm_iterations < cold_iterations);
}
