// The contact kernel's results have the same bits for any OpenMP thread count: the half-space
// product runs over fixed blocks of rows/columns with one FFTW plan per block size, the solver's
// cell sums over fixed blocks added in block order (half_space_operator.hpp, contact_solver.cpp).
#include <doctest/doctest.h>

#include <omp.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/half_space_operator.hpp"
#include "kernels/contact/sweep.hpp"
#include "rough_fixture.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;

namespace {
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Runs f with `threads` OpenMP threads, then restores the previous count.
template <class F>
void with_threads(int threads, F&& f) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  f();
  omp_set_num_threads(before);
}
}  // namespace

TEST_CASE("half-space product: same bits on 1 and 2 threads") {
  // 300 × 242 (padded 600 × 484: threads from 2^18 points on): whole and partial blocks of rows (8)
  // and of columns (8 of the 301 complex ones).
  const Grid grid{300, 242, 1e-6, 1.3e-6};
  HalfSpaceOperator op(grid, 115.4e9);
  std::vector<double> p(grid.size()), u1(grid.size()), u2(grid.size());
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = 1e9 * (1.1 + std::sin(0.37 * static_cast<double>(k)));
  with_threads(1, [&] { op.apply(p.data(), u1.data()); });
  with_threads(2, [&] { op.apply(p.data(), u2.data()); });
  CHECK(same_bits(u1, u2));
  // Direct sums over chosen cells (Eq. 3b): ~4 800 sources, ~24 000 targets, split among threads.
  std::vector<std::uint32_t> sources, targets;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (k % 15 == 0) sources.push_back(static_cast<std::uint32_t>(k));
    if (k % 3 == 0) targets.push_back(static_cast<std::uint32_t>(k));
  }
  with_threads(1, [&] { op.apply_direct(p.data(), sources, targets, u1.data()); });
  with_threads(2, [&] { op.apply_direct(p.data(), sources, targets, u2.data()); });
  CHECK(same_bits(u1, u2));
}

TEST_CASE("contact solve and sweep: same bits on 1 and 2 threads (rough, elastic-plastic, coarse start)") {
  const Hertz h;
  // Even 256², 60 cells per contact radius: the products (padded 512²) and, at the last steps, the
  // cell loops (A > 16 384 cells) run on the threads; the coarse start (README Eq. 16) on 128², 64².
  const double dx = h.a() / 60.0;
  const Grid grid{256, 256, dx, dx};
  const auto gap =
      ball_gap(grid, h.radius, rollspec::contact::test::wavy_heights(grid, 0.15 * h.approach, 0.4 * h.a()));
  SolverOptions opt;
  opt.hardness = 0.5 * h.p0();
  opt.tolerance = 1e-10;
  // From a few micro-contacts (direct sums, Eq. 3b) to the whole spot (DC-FFT).
  const std::vector<double> approaches = {-0.05 * h.approach, 0.3 * h.approach, 0.8 * h.approach, h.approach};
  std::vector<ContactResult> r[2];
  std::vector<double> p[2];
  for (int k = 0; k < 2; ++k)
    with_threads(k + 1, [&] {
      ContactSolver solver(grid, h.e_star);
      r[k] = sweep(solver, gap, approaches, opt, &p[k]);
    });
  REQUIRE(all_converged(r[0]));
  CHECK(r[0].front().coarse_iterations > 0);
  CHECK(r[0].back().plastic_cells > 0);
  CHECK(same_bits(p[0], p[1]));
  for (std::size_t j = 0; j < approaches.size(); ++j) {
    CHECK(r[0][j].iterations == r[1][j].iterations);
    CHECK(r[0][j].coarse_iterations == r[1][j].coarse_iterations);
    CHECK(same_bits(r[0][j].force, r[1][j].force));
    CHECK(same_bits(r[0][j].stiffness, r[1][j].stiffness));
    CHECK(same_bits(r[0][j].error, r[1][j].error));
  }
}
