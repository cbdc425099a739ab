// Blocked force F0 and stiffness k0 along a strip (blocked_force.hpp, BF-1 … BF-7; seed 002 §4.2,
// kernels/README.md D-11): Hertz on a smooth strip, quasi-static Hertz on a long wave, load search,
// warm start vs cold solves vs the whole strip, PSD peak, and the confinement check (BF-5).
#include <doctest/doctest.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hertz_fixture.hpp"
#include "kernels/contact/blocked_force.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/spectral/welch.hpp"
#include "rough_fixture.hpp"
#include "strip_fixture.hpp"

using namespace rollspec::contact;
using namespace rollspec::contact::test;

namespace {

double hertz_force(const Hertz& h, double d) { return hertz::force_at_approach(h.radius, h.e_star, d); }

double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::fabs(a[k] / b[k] - 1.0));
  return worst;
}

}  // namespace

TEST_CASE("smooth strip: F0 constant, equal to Hertz P(d0); k0 = 2E*a; load search finds the Hertz approach") {
  const Hertz h;
  // 32 cells per contact radius: the existing Hertz test's accuracy (force within 1e-4, measured
  // 5.0e-5; k within 1e-3 of 2E*a with the sub-cell contact edge, README Eq. 13–15). Window
  // half-width 1.6a (the rigid interference reaches √2 a, BF-5).
  const StripCase c = strip_case(h, 32.0, 1.6, 40);
  const auto x = cell_positions(c.strip, -18, 3, 12);
  ContactSolver solver(c.window, h.e_star);
  const BlockedForcePath path = blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, h.approach);
  REQUIRE(path.converged);
  REQUIRE(path.force.size() == x.size());
  const double p_hertz = h.force();
  double spread = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    spread = std::max(spread, std::fabs(path.force[k] / path.force[0] - 1.0));
    CHECK(std::fabs(path.force[k] / p_hertz - 1.0) < 1e-4);
  }
  CHECK(spread < 1e-12);  // the window moves with the ball: the same problem at every position
  CHECK(path.mean_force == doctest::Approx(path.force[0]).epsilon(1e-12));
  CHECK(std::fabs(path.k0 / h.stiffness() - 1.0) < 1e-3);
  CHECK(path.approach == h.approach);
  CHECK(path.paths == 1);
  CHECK(path.solves == 12);
  MESSAGE("smooth strip 32 cells/a: F0/P_Hertz - 1 = "
          << path.force[0] / p_hertz - 1.0 << ", spread " << spread << ", k0/(2E*a) - 1 = "
          << path.k0 / h.stiffness() - 1.0 << " (frozen set alone " << path.k0_frozen / h.stiffness() - 1.0 << ")"
          << ", CG iterations " << path.iterations << " for " << path.solves << " solves (cold first)");

  // Load search (BF-3): W = P_Hertz(w0) must give d0 = w0 within the force error · 2/3.
  const BlockedForcePath at_load =
      blocked_force_at_load(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, p_hertz);
  REQUIRE(at_load.converged);
  CHECK(std::fabs(at_load.mean_force / p_hertz - 1.0) < 1e-8);
  CHECK(std::fabs(at_load.approach / h.approach - 1.0) < 1e-4);
  const double a0 = std::sqrt(h.radius * at_load.approach);
  CHECK(std::fabs(at_load.k0 / (2.0 * h.e_star * a0) - 1.0) < 1e-3);
  MESSAGE("smooth load search: d0/w0 - 1 = " << at_load.approach / h.approach - 1.0
                                             << ", mean F0/W - 1 = " << at_load.mean_force / p_hertz - 1.0 << ", "
                                             << at_load.paths << " paths, " << at_load.solves << " solves");
}

TEST_CASE("smooth strip, solver grid = strip grid: the pressure is shifted by the step (BF-6)") {
  const Hertz h;
  // 16 cells/a: the existing Hertz accuracy there is 1.2e-4 (force).
  const Grid strip{101, 53, h.a() / 16.0, h.a() / 16.0};
  const auto x = cell_positions(strip, -12, 2, 13);
  ContactSolver solver(strip, h.e_star);
  const BlockedForcePath path = blocked_force_path(solver, strip, {}, h.radius, BallShape::Paraboloid, x, h.approach);
  REQUIRE(path.converged);
  double spread = 0.0;
  for (double f : path.force) spread = std::max(spread, std::fabs(f / path.force[0] - 1.0));
  CHECK(spread < 1e-9);  // the ball moves through the grid: equal up to the solver's tolerance
  CHECK(std::fabs(path.force[0] / h.force() - 1.0) < 2e-4);
  // The exact shifted start leaves little to do: far fewer iterations than cold solves.
  BlockedForceOptions cold;
  cold.warm_start = PathWarmStart::Cold;
  SolverOptions no_k;
  no_k.compute_stiffness = false;
  const BlockedForcePath warm_path =
      blocked_force_path(solver, strip, {}, h.radius, BallShape::Paraboloid, x, h.approach, no_k);
  const BlockedForcePath cold_path =
      blocked_force_path(solver, strip, {}, h.radius, BallShape::Paraboloid, x, h.approach, no_k, cold);
  REQUIRE(cold_path.converged);
  CHECK(max_relative_difference(warm_path.force, cold_path.force) < 1e-8);
  CHECK(std::isnan(warm_path.k0));
  CHECK(warm_path.iterations < cold_path.iterations / 2);
  MESSAGE("smooth, grid = strip: spread " << spread << ", iterations warm " << warm_path.iterations << ", cold "
                                          << cold_path.iterations);
}

TEST_CASE("rough elastic-plastic strip: warm starts equal cold solves and whole-strip solves") {
  const Hertz h;
  const StripCase c = strip_case(h, 12.0, 1.9, 36, 10);  // the window is narrower than the strip
  const auto heights = rollspec::contact::test::wavy_heights(c.strip, 0.15 * h.approach, 0.4 * h.a());
  const auto x = cell_positions(c.strip, -15, 2, 16);
  SolverOptions opt;
  opt.hardness = 0.5 * h.p0();
  ContactSolver window_solver(c.window, h.e_star);
  BlockedForceOptions ball, strip_frame, cold;
  strip_frame.warm_start = PathWarmStart::Strip;
  cold.warm_start = PathWarmStart::Cold;
  const auto run = [&](const BlockedForceOptions& o) {
    return blocked_force_path(window_solver, c.strip, heights, h.radius, BallShape::Sphere, x, h.approach, opt, o);
  };
  const BlockedForcePath p_ball = run(ball), p_strip = run(strip_frame), p_cold = run(cold);
  REQUIRE(p_ball.converged);
  REQUIRE(p_strip.converged);
  REQUIRE(p_cold.converged);
  CHECK(max_relative_difference(p_ball.force, p_cold.force) < 1e-8);
  CHECK(max_relative_difference(p_strip.force, p_cold.force) < 1e-8);
  CHECK(max_relative_difference(p_ball.stiffness, p_cold.stiffness) < 1e-8);

  // Reference: each position solved cold on the whole strip (ball_gap with centre_x = x_k).
  ContactSolver strip_solver(c.strip, h.e_star);
  std::vector<double> whole(x.size());
  std::size_t plastic = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    std::vector<double> p;
    const auto gap = ball_gap(c.strip, h.radius, heights, BallShape::Sphere, x[k]);
    const ContactResult r = strip_solver.solve(gap, h.approach, p, opt);
    REQUIRE(r.converged);
    whole[k] = r.force;
    plastic += r.plastic_cells;
  }
  CHECK(plastic > 0);  // the cap is active
  CHECK(max_relative_difference(p_ball.force, whole) < 1e-8);
  // Literal form: the solver's grid is the strip, the field shifted by the step.
  const BlockedForcePath p_grid =
      blocked_force_path(strip_solver, c.strip, heights, h.radius, BallShape::Sphere, x, h.approach, opt);
  REQUIRE(p_grid.converged);
  CHECK(max_relative_difference(p_grid.force, whole) < 1e-8);
  // Off-centre path y_c = 3.4 dy (window rows shifted by 3, ball 0.4 cell off the cell centres).
  BlockedForceOptions off_centre;
  off_centre.centre_y = 3.4 * c.strip.dy;
  const std::vector<double> x6(x.begin(), x.begin() + 6);
  const BlockedForcePath p_off =
      blocked_force_path(window_solver, c.strip, heights, h.radius, BallShape::Sphere, x6, h.approach, opt, off_centre);
  REQUIRE(p_off.converged);
  std::vector<double> whole_off(x6.size());
  for (std::size_t k = 0; k < x6.size(); ++k) {
    std::vector<double> p;
    const auto gap = ball_gap(c.strip, h.radius, heights, BallShape::Sphere, x6[k], off_centre.centre_y);
    const ContactResult r = strip_solver.solve(gap, h.approach, p, opt);
    REQUIRE(r.converged);
    whole_off[k] = r.force;
  }
  CHECK(max_relative_difference(p_off.force, whole_off) < 1e-8);
  CHECK(std::fabs(p_off.force[0] / whole[0] - 1.0) > 1e-4);  // a different path indeed

  // Load search on the rough path (BF-3): mean F0 = W, with and without stored fields (BF-6').
  const double load = 1.1 * p_cold.mean_force;
  BlockedForceOptions first_only;
  first_only.max_stored_bytes = 0;
  const BlockedForcePath l_all =
      blocked_force_at_load(window_solver, c.strip, heights, h.radius, BallShape::Sphere, x, load, opt);
  const BlockedForcePath l_first =
      blocked_force_at_load(window_solver, c.strip, heights, h.radius, BallShape::Sphere, x, load, opt, first_only);
  REQUIRE(l_all.converged);
  REQUIRE(l_first.converged);
  CHECK(std::fabs(l_all.mean_force / load - 1.0) < 1e-8);
  CHECK(std::fabs(l_first.mean_force / load - 1.0) < 1e-8);
  CHECK(l_all.approach > h.approach);
  CHECK(l_all.approach == doctest::Approx(l_first.approach).epsilon(1e-8));
  MESSAGE("rough load search: d0/w0 = " << l_all.approach / h.approach << ", k0 = " << l_all.k0 << " N/m, "
                                        << l_all.paths << " paths; CG iterations with stored fields "
                                        << l_all.iterations << ", first position only " << l_first.iterations);
  const auto [fmin, fmax] = std::minmax_element(whole.begin(), whole.end());
  CHECK(*fmax / *fmin > 1.003);  // the force varies along this path (measured 0.49 %) far above 1e-8
  MESSAGE("rough path (16 positions, " << plastic << " plastic cells in all): CG iterations ball-frame "
                                       << p_ball.iterations << ", strip-frame " << p_strip.iterations << ", cold "
                                       << p_cold.iterations << ", grid = strip " << p_grid.iterations << "; F0 range "
                                       << *fmin << " .. " << *fmax << " N");
}

TEST_CASE("long wave: F0 follows quasi-static Hertz, mean F0 = W, k0 = dF/dd, PSD peak at 1/lambda") {
  const Hertz h;
  // 8 cells/a, step Δx = a (8 cells), λ = 24a = 24 samples, A = 0.02 w0, 192 positions (8 λ).
  const double cells = 8.0;
  const std::size_t count = 192;
  const long step = 8;
  const Grid window = h.grid(cells, 1.6);
  const std::size_t extra = static_cast<std::size_t>(step) * (count - 1) + 2;
  const Grid strip{window.nx + extra, window.ny, window.dx, window.dy};
  const double lambda = 24.0 * h.a(), amplitude = 0.02 * h.approach;
  std::vector<double> heights(strip.size());
  for (std::size_t iy = 0; iy < strip.ny; ++iy)
    for (std::size_t ix = 0; ix < strip.nx; ++ix)
      heights[iy * strip.nx + ix] = amplitude * std::cos(2.0 * kPi * strip.x(ix) / lambda);
  const long first = -static_cast<long>(extra / 2) + 0;
  const auto x = cell_positions(strip, first, step, count);
  const double load = h.force();
  ContactSolver solver(window, h.e_star);
  const auto t0 = std::chrono::steady_clock::now();
  const BlockedForcePath path = blocked_force_at_load(solver, strip, heights, h.radius, BallShape::Paraboloid, x, load);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(path.converged);
  CHECK(std::fabs(path.mean_force / load - 1.0) < 1e-8);
  CHECK(path.presearch_paths > 0);  // 192 ≥ 4·32 positions: pre-search on every 6th (BF-4')
  BlockedForceOptions no_presearch;
  no_presearch.presearch_positions = 0;
  const BlockedForcePath direct =
      blocked_force_at_load(solver, strip, heights, h.radius, BallShape::Paraboloid, x, load, {}, no_presearch);
  REQUIRE(direct.converged);
  CHECK(direct.presearch_paths == 0);
  CHECK(direct.approach == doctest::Approx(path.approach).epsilon(1e-8));

  // Quasi-static Hertz following the wave: F0(x) ≈ P(d0 + h(x)). Stated tolerance 1e-3 of P:
  // Hertz discretisation at 8 cells/a (4.1e-4, README table) plus the wave's curvature
  // (relative change of the gap curvature R A q² = 1.4e-3 at the crest, force change ≈ a quarter).
  double worst = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double hk = amplitude * std::cos(2.0 * kPi * x[k] / lambda);
    worst = std::max(worst, std::fabs(path.force[k] / hertz_force(h, path.approach + hk) - 1.0));
  }
  CHECK(worst < 1e-3);
  // d0 from the continuum: mean_k P(d + h(x_k)) = W (Newton on the analytic path mean).
  double d_ref = h.approach;
  for (int it = 0; it < 50; ++it) {
    double f = 0.0, df = 0.0;
    for (double xk : x) {
      const double dk = d_ref + amplitude * std::cos(2.0 * kPi * xk / lambda);
      f += hertz_force(h, dk);
      df += 2.0 * h.e_star * std::sqrt(h.radius * dk);
    }
    d_ref += (load * static_cast<double>(count) - f) / df;
  }
  CHECK(std::fabs(path.approach / d_ref - 1.0) < 5e-4);

  // The frozen-set mean K̄_f is the derivative of the path mean (BF-3): central difference over
  // d0 ± 1e-5 d0. (k0 adds the sub-cell edge, README Eq. 13–15, and is not the discrete slope.)
  SolverOptions no_k;
  no_k.compute_stiffness = false;
  const double dd = 1e-5 * path.approach;
  const BlockedForcePath up =
      blocked_force_path(solver, strip, heights, h.radius, BallShape::Paraboloid, x, path.approach + dd, no_k);
  const BlockedForcePath down =
      blocked_force_path(solver, strip, heights, h.radius, BallShape::Paraboloid, x, path.approach - dd, no_k);
  REQUIRE(up.converged);
  REQUIRE(down.converged);
  const double k_fd = (up.mean_force - down.mean_force) / (2.0 * dd);
  CHECK(std::fabs(path.k0_frozen / k_fd - 1.0) < 1e-6);

  // PSD of F0 along the path, f_s = 1/Δx (cycles/m): peak at 1/λ (bin 4 of a 96-sample segment).
  rollspec::spectral::WelchConfig cfg;
  cfg.sample_rate = 1.0 / (static_cast<double>(step) * strip.dx);
  cfg.segment = 96;
  cfg.overlap = 48;
  rollspec::spectral::WelchPlan plan(cfg);
  rollspec::spectral::WelchWorkspace ws(cfg.segment);
  std::vector<double> psd(plan.n_freq());
  plan.psd(path.force.data(), path.force.size(), psd.data(), ws);
  const auto freqs = plan.frequencies();
  const std::size_t peak = static_cast<std::size_t>(std::max_element(psd.begin() + 1, psd.end()) - psd.begin());
  CHECK(std::fabs(freqs[peak] * lambda - 1.0) < 1e-9);
  double others = 0.0;
  for (std::size_t i = 1; i < psd.size(); ++i)
    if (i + 1 < peak || i > peak + 1) others = std::max(others, psd[i]);
  // A single line: Hann leakage reaches the neighbours only (segment = 4 λ); the largest other
  // bin is the second harmonic of the Hertz nonlinearity, power ratio ≈ ((A/d0)/8)² = 6e-6
  // (measured 4.2e-6, with the grid's ring effects).
  CHECK(psd[peak] > 1e5 * others);
  CHECK(psd[2 * peak] / psd[peak] < 1e-5);
  MESSAGE("long wave: " << path.paths << " paths + " << path.presearch_paths
                        << " pre-search paths (without: " << direct.paths << " paths, " << direct.solves << " solves), "
                        << path.solves << " solves, " << path.iterations << " CG + " << path.stiffness_iterations
                        << " stiffness iterations, " << seconds << " s (" << 1e3 * seconds / path.solves
                        << " ms per solve); max |F0/P(d0+h) - 1| = " << worst << ", d0/d_ref - 1 = "
                        << path.approach / d_ref - 1.0 << ", k0_frozen/k_fd - 1 = " << path.k0_frozen / k_fd - 1.0
                        << ", k0/k_fd - 1 = " << path.k0 / k_fd - 1.0 << ", PSD peak / next-but-one "
                        << psd[peak] / others);
}

TEST_CASE("confinement (BF-5) and bad input are refused with the position named") {
  const Hertz h;
  const StripCase c = strip_case(h, 8.0, 1.6, 20);
  const auto x = cell_positions(c.strip, -5, 2, 6);
  ContactSolver solver(c.window, h.e_star);
  CHECK_NOTHROW(blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, h.approach));
  // Window half-length 1.0a < √2 a in x: interference outside the window at the first position.
  const Grid short_window{17, c.window.ny, c.window.dx, c.window.dy};
  ContactSolver short_solver(short_window, h.e_star);
  const std::string m1 = thrown_message(
      [&] { blocked_force_path(short_solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, h.approach); });
  CHECK(m1.find("position 0") != std::string::npos);
  CHECK(m1.find("outside the solver window") != std::string::npos);
  // Path running off the strip's end (half-length 23 cells): the window clamps, the interference
  // (radius √2 a = 11.3 cells) reaches the last column at x = 12 cells, position 6.
  const auto off = cell_positions(c.strip, 0, 2, 8);
  const std::string m2 = thrown_message(
      [&] { blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, off, h.approach); });
  CHECK(m2.find("position 6") != std::string::npos);
  CHECK(m2.find("strip's edge") != std::string::npos);
  // The load search stays within BF-5 and names the limiting position when the load needs more:
  // at 3 W the contact radius 1.44 a reaches √2·1.44 a = 2.0 a > 1.6 a (the window's half-length).
  const std::string m4 = thrown_message(
      [&] { blocked_force_at_load(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, 3.0 * h.force()); });
  CHECK(m4.find("exceeds the mean force") != std::string::npos);
  CHECK(m4.find("at position") != std::string::npos);
  // A strip too narrow in y for the contact.
  const Grid narrow_window{c.window.nx, 15, c.window.dx, c.window.dy};
  const Grid narrow_strip{c.strip.nx, 15, c.strip.dx, c.strip.dy};
  ContactSolver narrow_solver(narrow_window, h.e_star);
  const std::string m3 = thrown_message(
      [&] { blocked_force_path(narrow_solver, narrow_strip, {}, h.radius, BallShape::Paraboloid, x, h.approach); });
  CHECK(m3.find("strip's edge (first row)") != std::string::npos);
  // A window too narrow in y (half-width 1.0a) on the wide strip.
  const Grid thin_window{c.window.nx, 17, c.window.dx, c.window.dy};
  ContactSolver thin_solver(thin_window, h.e_star);
  const std::string m5 = thrown_message(
      [&] { blocked_force_path(thin_solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, h.approach); });
  CHECK(m5.find("position 0") != std::string::npos);
  CHECK(m5.find("outside the solver window") != std::string::npos);
  // Steps that are not whole cells, not increasing; mismatched grids and sizes; bad load.
  std::vector<double> half_step = x;
  half_step[3] += 0.5 * c.strip.dx;
  CHECK(thrown_message([&] {
          blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, half_step, h.approach);
        }).find("step 3") != std::string::npos);
  std::vector<double> back = x;
  back[2] = back[1];
  CHECK_THROWS_AS(blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, back, h.approach),
                  std::invalid_argument);
  const Grid other{c.strip.nx, c.strip.ny, 1.01 * c.strip.dx, c.strip.dy};
  CHECK_THROWS_AS(blocked_force_path(solver, other, {}, h.radius, BallShape::Paraboloid, x, h.approach),
                  std::invalid_argument);
  CHECK_THROWS_AS(
      blocked_force_path(solver, c.strip, std::vector<double>(7, 0.0), h.radius, BallShape::Paraboloid, x, h.approach),
      std::invalid_argument);
  CHECK_THROWS_AS(blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, {}, h.approach),
                  std::invalid_argument);
  CHECK_THROWS_AS(blocked_force_at_load(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, 0.0),
                  std::invalid_argument);
  ContactSolver periodic(c.window, h.e_star, Boundary::Periodic);
  CHECK_THROWS_AS(blocked_force_path(periodic, c.strip, {}, h.radius, BallShape::Paraboloid, x, h.approach),
                  std::invalid_argument);
  // No contact anywhere (approach below the ball): F0 = 0, k = 0, converged.
  const BlockedForcePath none =
      blocked_force_path(solver, c.strip, {}, h.radius, BallShape::Paraboloid, x, -h.approach);
  CHECK(none.converged);
  CHECK(none.mean_force == 0.0);
  CHECK(none.k0 == 0.0);
}

TEST_CASE("chunked path (BF-6c): the same bits on 1 and 2 threads, equal to the unchunked path") {
  const WavyStrip strip;
  BlockedForceOptions whole, chunked;
  chunked.chunk_positions = 5;    // chunks 5, 5, 5, 1: one shorter than the rest
  const double load = 1.1 * 3.0;  // N, about the mean force of this path at the Hertz approach
  const auto at_load = [&](int threads, const BlockedForceOptions& o) { return strip.at_load(threads, load, o); };
  const BlockedForcePath one = at_load(1, chunked), two = at_load(2, chunked), ref = at_load(2, whole);
  REQUIRE(one.converged);
  REQUIRE(two.converged);
  REQUIRE(ref.converged);
  CHECK(std::memcmp(one.force.data(), two.force.data(), sizeof(double) * one.force.size()) == 0);
  CHECK(std::memcmp(one.stiffness.data(), two.stiffness.data(), sizeof(double) * one.stiffness.size()) == 0);
  CHECK(std::memcmp(&one.approach, &two.approach, sizeof(double)) == 0);
  CHECK(one.iterations == two.iterations);
  CHECK(one.paths == two.paths);
  CHECK(max_relative_difference(one.force, ref.force) < 1e-8);
  CHECK(max_relative_difference(one.stiffness, ref.stiffness) < 1e-8);
  CHECK(one.approach == doctest::Approx(ref.approach).epsilon(1e-8));
  MESSAGE("chunks of 5: CG iterations " << one.iterations << " (unchunked " << ref.iterations
                                        << "), max relative "
                                           "force difference to the unchunked path "
                                        << max_relative_difference(one.force, ref.force));
}

TEST_CASE("loose cold path (BF-4''): the root of the exact search, never itself the result") {
  const WavyStrip strip;
  BlockedForceOptions loose, exact;
  exact.cold_tolerance = 0.0;  // every path to the solver's tolerances (the search before BF-4'')
  const auto at_load = [&](double load, const BlockedForceOptions& o) {
    return strip.at_load(omp_get_max_threads(), load, o);
  };
  const double w = 1.3 * 3.0;  // N, off the Hertz start: several paths
  const BlockedForcePath a = at_load(w, loose), b = at_load(w, exact);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK(a.paths >= 2);  // the loose first path only places the Newton step
  CHECK(std::fabs(a.mean_force / w - 1.0) < 1e-8);
  CHECK(a.approach == doctest::Approx(b.approach).epsilon(1e-8));
  CHECK(max_relative_difference(a.force, b.force) < 1e-8);
  CHECK(max_relative_difference(a.stiffness, b.stiffness) < 1e-8);
  CHECK(a.iterations + a.stiffness_iterations < b.iterations + b.stiffness_iterations);
  MESSAGE("loose cold path: " << a.paths << " paths, " << a.iterations << " + " << a.stiffness_iterations
                              << " CG + stiffness iterations; exact: " << b.paths << " paths, " << b.iterations << " + "
                              << b.stiffness_iterations);
}
