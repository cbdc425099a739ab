// Love coefficients (D-6) and the DC-FFT product against the direct O(N²) reference oracle.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "kernels/contact/direct_product.hpp"
#include "kernels/contact/half_space_operator.hpp"
#include "kernels/contact/love_influence.hpp"
#include "kernels/contact/version.hpp"

using namespace rollspec::contact;

namespace {
constexpr double kPi = 3.14159265358979323846;

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}
std::vector<double> test_pressure(std::size_t n) {
  std::vector<double> p(n);
  for (std::size_t k = 0; k < n; ++k)
    p[k] = 1.0e6 * (1.3 + std::sin(1.7 * static_cast<double>(k)) + 0.4 * std::cos(0.31 * static_cast<double>(k * k)));
  return p;
}
}  // namespace

TEST_CASE("Love coefficient: centre of a square and far field") {
  const double e_star = 115.4e9, dx = 2e-6;
  // Centre of a square of side c under unit pressure: u = 4 c asinh(1)/(π E*) (Johnson Eq. 3.96).
  CHECK(love_coefficient(0, 0, dx, dx, e_star) ==
        doctest::Approx(4.0 * dx * std::asinh(1.0) / (kPi * e_star)).epsilon(1e-15));
  // Far field: ΔA/(π E*) times the cell average of 1/r, 1/x + (2a² − b²)/(6x³) + O(h⁴/x⁵).
  const double dy = 1.5e-6, a = dx / 2, b = dy / 2;
  for (long ox : {50L, 200L}) {
    const double x = static_cast<double>(ox) * dx;
    const double expected = dx * dy / (kPi * e_star) * (1.0 / x + (2 * a * a - b * b) / (6 * x * x * x));
    CHECK(love_coefficient(ox, 0, dx, dy, e_star) == doctest::Approx(expected).epsilon(1e-8));
  }
  // Symmetry in both offsets.
  CHECK(love_coefficient(3, -2, dx, dy, e_star) == love_coefficient(-3, 2, dx, dy, e_star));
}

TEST_CASE("DC-FFT product equals the direct O(N^2) sum to 1e-12") {
  const double e_star = 115.4e9;
  for (const Grid grid : {Grid{13, 9, 1.0e-6, 1.7e-6}, Grid{16, 16, 2.0e-6, 2.0e-6}, Grid{1, 7, 1e-6, 3e-6}}) {
    const std::vector<double> p = test_pressure(grid.size());
    const std::vector<double> ref = direct_product(grid, e_star, p);
    HalfSpaceOperator op(grid, e_star);
    std::vector<double> u(grid.size());
    op.apply(p.data(), u.data());
    std::vector<double> diff(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) diff[i] = u[i] - ref[i];
    const double rel = max_abs(diff) / max_abs(ref);
    MESSAGE("DC-FFT vs direct, " << grid.nx << "x" << grid.ny << ": max rel diff " << rel);
    CHECK(rel < 1e-12);
    // Plans are re-executed: a second product (after another field) is bitwise the same.
    std::vector<double> u2(grid.size()), junk = test_pressure(grid.size() + 3);
    op.apply(junk.data(), u2.data());
    op.apply(p.data(), u2.data());
    CHECK(u2 == u);
  }
}

TEST_CASE("open padding: the smallest 2^a 3^b 5^c 7^d >= 2n - 1, exact against the direct sum") {
  // README Eq. 3: any cyclic length >= 2n - 1 gives the aperiodic product exactly.
  CHECK(fast_fft_length(1) == 1);
  CHECK(fast_fft_length(1019) == 1024);  // side 510 (was 1020 = 2^2 3 5 17)
  CHECK(fast_fft_length(1021) == 1024);  // side 511 (was 1022 = 2 7 73)
  CHECK(fast_fft_length(1023) == 1024);  // side 512 (unchanged)
  CHECK(fast_fft_length(73) == 75);
  CHECK(fast_fft_length(97) == 98);
  const double e_star = 115.4e9;
  // Padding shorter than 2n (75, 60), rows of padding more or fewer than ny, ny below one row block
  // (one kernel plan), ny not a multiple of the block (overlapping kernel blocks).
  for (const Grid grid : {Grid{38, 30, 1.0e-6, 1.3e-6}, Grid{61, 47, 2.0e-6, 2.0e-6}, Grid{9, 5, 1e-6, 1e-6},
                          Grid{5, 11, 1e-6, 2e-6}, Grid{49, 49, 1e-6, 1e-6}}) {
    const std::vector<double> p = test_pressure(grid.size());
    const std::vector<double> ref = direct_product(grid, e_star, p);
    HalfSpaceOperator op(grid, e_star);
    CHECK(op.fft_nx() == fast_fft_length(2 * grid.nx - 1));
    CHECK(op.fft_ny() == fast_fft_length(2 * grid.ny - 1));
    std::vector<double> u(grid.size());
    op.apply(p.data(), u.data());
    std::vector<double> diff(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) diff[i] = u[i] - ref[i];
    const double rel = max_abs(diff) / max_abs(ref);
    MESSAGE("padded " << op.fft_nx() << "x" << op.fft_ny() << " for " << grid.nx << "x" << grid.ny
                      << ": max rel diff to the direct sum " << rel);
    CHECK(rel < 1e-12);
  }
}

TEST_CASE("direct sums over chosen cells (Eq. 3b) equal the direct O(N^2) sum to 1e-13") {
  const double e_star = 115.4e9;
  for (const Grid grid : {Grid{13, 9, 1.0e-6, 1.7e-6}, Grid{40, 32, 2.0e-6, 2.0e-6}, Grid{1, 7, 1e-6, 3e-6}}) {
    // Sources: a run-rich blob plus scattered cells, rows ending at the grid's edge included.
    std::vector<double> p(grid.size(), 0.0);
    std::vector<std::uint32_t> sources, targets;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const std::size_t ix = i % grid.nx, iy = i / grid.nx;
      if ((ix + 2 * iy) % 7 < 3 || ix + 1 == grid.nx) {
        sources.push_back(static_cast<std::uint32_t>(i));
        p[i] = 1e6 * (1.0 + 0.3 * std::sin(0.7 * static_cast<double>(i)));
      }
      if (i % 3 != 1) targets.push_back(static_cast<std::uint32_t>(i));
    }
    const std::vector<double> ref = direct_product(grid, e_star, p);
    HalfSpaceOperator op(grid, e_star);
    std::vector<double> u(grid.size(), -1.0);
    op.apply_direct(p.data(), sources, targets, u.data());
    double diff = 0.0;
    for (std::uint32_t t : targets) diff = std::max(diff, std::fabs(u[t] - ref[t]));
    MESSAGE("direct sums on chosen cells vs direct, " << grid.nx << "x" << grid.ny << ": max rel diff "
                                                      << diff / max_abs(ref));
    CHECK(diff < 1e-13 * max_abs(ref));
    for (std::size_t i = 0; i < grid.size(); ++i)
      if (i % 3 == 1) CHECK(u[i] == -1.0);  // cells that are not targets are not written
  }
  HalfSpaceOperator periodic(Grid{8, 8, 1e-6, 1e-6}, e_star, Boundary::Periodic);
  std::vector<double> p(64, 1.0), u(64);
  CHECK_THROWS_AS(periodic.apply_direct(p.data(), {0}, {0}, u.data()), std::logic_error);
}

TEST_CASE("periodic operator: Boussinesq symbol 2/(E* q) on a Fourier mode, zero mean mode") {
  const double e_star = 200e9;
  const Grid grid{32, 8, 1e-6, 1e-6};
  HalfSpaceOperator op(grid, e_star, Boundary::Periodic);
  const double lambda = 32e-6, q = 2 * kPi / lambda;
  std::vector<double> p(grid.size()), u(grid.size());
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix)
      p[iy * grid.nx + ix] = 1e6 + 3e5 * std::cos(q * static_cast<double>(ix) * grid.dx);
  op.apply(p.data(), u.data());
  double err = 0.0;
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix) {
      const double expected = 2.0 / (e_star * q) * 3e5 * std::cos(q * static_cast<double>(ix) * grid.dx);
      err = std::max(err, std::fabs(u[iy * grid.nx + ix] - expected));
    }
  CHECK(err < 1e-12 * 2.0 / (e_star * q) * 3e5);
}

TEST_CASE("operators built and applied concurrently agree with the serial product") {
  const double e_star = 115.4e9;
  const Grid grid{24, 20, 1e-6, 1e-6};
  const std::vector<double> p = test_pressure(grid.size());
  std::vector<double> serial(grid.size());
  {
    HalfSpaceOperator op(grid, e_star);
    op.apply(p.data(), serial.data());
  }
  std::vector<std::vector<double>> results(8, std::vector<double>(grid.size()));
#pragma omp parallel for num_threads(2)
  for (int k = 0; k < 8; ++k) {
    HalfSpaceOperator op(grid, e_star);
    op.apply(p.data(), results[static_cast<std::size_t>(k)].data());
  }
  for (const auto& r : results) CHECK(r == serial);
}

#include "kernels/spectral/welch.hpp"

// Contact and spectral plans once took two different planner locks, so a contact operator and a
// Welch plan made at the same time raced in FFTW's planner. Both now take the one lock.
TEST_CASE("contact operators and Welch plans made at the same time agree with serial ones") {
  const double e_star = 115.4e9;
  const Grid grid{24, 20, 1e-6, 1e-6};
  const std::vector<double> p = test_pressure(grid.size());
  rollspec::spectral::WelchConfig wc;
  wc.sample_rate = 1000.0;
  wc.segment = 96;
  wc.overlap = 48;
  std::vector<double> serial_u(grid.size()), serial_psd(wc.segment / 2 + 1);
  {
    HalfSpaceOperator op(grid, e_star);
    op.apply(p.data(), serial_u.data());
    const rollspec::spectral::WelchPlan plan(wc);
    rollspec::spectral::WelchWorkspace ws(wc.segment);
    plan.psd(p.data(), p.size(), serial_psd.data(), ws);
  }
  const int n = 64;
  std::vector<std::vector<double>> results(static_cast<std::size_t>(n));
#pragma omp parallel for num_threads(2) schedule(static, 1)
  for (int k = 0; k < n; ++k) {
    auto& r = results[static_cast<std::size_t>(k)];
    if (k % 2 == 0) {
      r.resize(grid.size());
      HalfSpaceOperator op(grid, e_star);
      op.apply(p.data(), r.data());
    } else {
      r.resize(serial_psd.size());
      const rollspec::spectral::WelchPlan plan(wc);
      rollspec::spectral::WelchWorkspace ws(wc.segment);
      plan.psd(p.data(), p.size(), r.data(), ws);
    }
  }
  for (int k = 0; k < n; ++k) CHECK(results[static_cast<std::size_t>(k)] == (k % 2 == 0 ? serial_u : serial_psd));
}

#include "kernels/contact/geometry.hpp"

TEST_CASE("ball gap: exact sphere, paraboloid, roughness and composite heights") {
  const Grid grid{5, 3, 1e-3, 2e-3};
  const double radius = 0.02;
  const std::vector<double> h1{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  std::vector<double> h2(h1.size(), 0.5e-6), h(h1.size());
  for (std::size_t i = 0; i < h1.size(); ++i) h[i] = 1e-7 * h1[i];
  const auto sphere = ball_gap(grid, radius, {});
  const auto para = ball_gap(grid, radius, {}, BallShape::Paraboloid);
  const auto rough = ball_gap(grid, radius, composite_heights(h, h2));
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix) {
      const std::size_t i = iy * grid.nx + ix;
      const double r2 = grid.x(ix) * grid.x(ix) + grid.y(iy) * grid.y(iy);
      CHECK(sphere[i] == doctest::Approx(radius - std::sqrt(radius * radius - r2)).epsilon(1e-9));
      CHECK(para[i] == doctest::Approx(r2 / (2 * radius)).epsilon(1e-15));
      CHECK(rough[i] == doctest::Approx(sphere[i] - h[i] - h2[i]).epsilon(1e-14));
    }
  CHECK(sphere[7] == 0.0);  // centre cell (2, 1) sits at the origin
  CHECK_THROWS_AS(ball_gap(grid, radius, std::vector<double>(4)), std::invalid_argument);
}

TEST_CASE("kernel version is a positive integer constant") {
  static_assert(rollspec::contact::kernel_version >= 1, "kernel_version starts at 1");
  // 2: the stiffness carries the sub-cell contact edge (README Eq. 13–15); tables of version 1 are refused.
  // 3: the faster solve (README Eq. 3a, 7a, 16) changes last bits; tables of version 2 are refused.
  CHECK(rollspec::contact::kernel_version == 8);
}
