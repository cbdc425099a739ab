// Grid sides 510, 511 and 512: each open axis is padded to fast_fft_length(2n − 1) = 1024 (README
// Eq. 3), not to 2n (1020 = 2^2·3·5·17, 1022 = 2·7·73). Any length ≥ 2n − 1 gives the aperiodic
// product exactly, so these sides must give the same product as direct sums (wrap-around would show
// between opposite corners) and a Hertz solve that agrees with the reference solver and with Hertz.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/half_space_operator.hpp"

using namespace rollspec::contact;
using rollspec::contact::test::Hertz;
using rollspec::contact::test::kPi;

namespace {

double rel(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

double max_rel_field(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0, m = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    d = std::max(d, std::fabs(a[i] - b[i]));
    m = std::max(m, std::fabs(b[i]));
  }
  return d / m;
}

}  // namespace

TEST_CASE("sides 510, 511, 512: padded to 1024, the product equals direct sums from opposite corners") {
  const double e_star = 115.4e9;
  for (std::size_t n : {std::size_t(510), std::size_t(511), std::size_t(512)}) {
    const Grid grid{n, n, 1.0e-6, 1.3e-6};
    HalfSpaceOperator op(grid, e_star);
    CHECK(op.fft_nx() == 1024);
    CHECK(op.fft_ny() == 1024);
    // 8 × 8 patches in three corners: pairs at offsets up to ±(n − 1) each way, where a padding
    // shorter than 2n − 1 would fold one corner's displacement onto the opposite one.
    std::vector<double> p(grid.size(), 0.0);
    std::vector<std::uint32_t> sources, targets(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) targets[i] = static_cast<std::uint32_t>(i);
    for (std::size_t iy = 0; iy < n; ++iy)
      for (std::size_t ix = 0; ix < n; ++ix) {
        const bool lo_x = ix < 8, hi_x = ix + 8 >= n, lo_y = iy < 8, hi_y = iy + 8 >= n;
        if ((lo_x && lo_y) || (hi_x && hi_y) || (hi_x && lo_y)) {
          const std::size_t i = iy * n + ix;
          p[i] = 1.0e6 * (1.5 + std::sin(0.37 * static_cast<double>(i)));
          sources.push_back(static_cast<std::uint32_t>(i));
        }
      }
    std::vector<double> u(grid.size()), direct(grid.size());
    op.apply(p.data(), u.data());
    op.apply_direct(p.data(), sources, targets, direct.data());  // checked against the O(N²) sum in test_influence
    const double d = max_rel_field(u, direct);
    MESSAGE("side " << n << ": DC-FFT on " << op.fft_nx() << "² vs direct sums, max rel diff " << d);
    CHECK(d < 1e-12);
  }
}

TEST_CASE("sides 510, 511, 512: Hertz solve = the reference solver to 1e-10 and Hertz to the grid's accuracy") {
  const Hertz h;
  double force_512 = 0.0;
  for (std::size_t n : {std::size_t(512), std::size_t(511), std::size_t(510)}) {
    // Contact radius 0.42 n cells: the displacement-control box (Eq. 3c) is the whole grid, so every
    // product runs on the 1024² padding.
    const double dx = h.a() / (0.42 * static_cast<double>(n));
    const Grid grid{n, n, dx, dx};
    const std::vector<double> gap = ball_gap(grid, h.radius, {}, BallShape::Paraboloid);
    ContactSolver fast(grid, h.e_star), ref(grid, h.e_star);
    SolverOptions opt;
    opt.compute_stiffness = false;
    std::vector<double> p_fast, p_ref;
    const ContactResult a = fast.solve(gap, h.approach, p_fast, opt);
    const ContactResult b = ref.solve_reference(gap, h.approach, p_ref, opt);
    REQUIRE(a.converged);
    REQUIRE(b.converged);
    MESSAGE("side " << n << ": " << a.iterations << " iterations (" << a.coarse_iterations << " coarse), force "
                    << a.force << " N, Hertz " << h.force() << " N, fast vs reference force " << rel(a.force, b.force)
                    << ", pressure " << max_rel_field(p_fast, p_ref));
    CHECK(rel(a.force, b.force) < 1e-10);
    CHECK(rel(a.max_pressure, b.max_pressure) < 1e-10);
    CHECK(max_rel_field(p_fast, p_ref) < 1e-10);
    // About 215 cells per contact radius: the discretisation error of the force is below 1e-4 from
    // 32 cells per radius on (test_hertz.cpp).
    CHECK(rel(a.force, h.force()) < 1e-4);
    CHECK(rel(a.max_pressure, h.p0()) < 1e-3);
    CHECK(rel(std::sqrt(a.contact_area / kPi), h.a()) < 1e-2);
    if (n == 512)
      force_512 = a.force;
    else
      CHECK(rel(a.force, force_512) < 1e-4);
  }
}
