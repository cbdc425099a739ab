// Contact kernel benchmark (issue 4). Prints CSV to stdout: case,n,seconds,ratio,iterations,note
//
//   cg_iteration   time per Polonsky–Keer CG iteration (seconds column) and its ratio to two
//                  DC-FFT convolutions of the same padded size, measured in the same run (goal ≤ 1.3)
//   convolution    time of one half-space product u = C p (padded 2n × 2n r2c/c2r)
//   hertz_solve    smooth 40 mm ball at 512², cold start, tolerance 1e-10; ratio = force error vs Hertz
//                  (wall seconds on all threads, plans made beforehand)
//   hertz_stiffness  the frozen-set stiffness solve on that field; ratio = k error vs 2E*a
//   seed_table     40 mm steel ball, E* = 115.4 GPa, H = 5 GPa, on Gaussian rough surfaces
//                  (σ = 0.3 µm, correlation length 10 µm) at 256², 20 approach steps × 10
//                  realisations, OpenMP over realisations; ratio = mean k at the step nearest the
//                  ball weight 2.58 N / smooth Hertz k there
//   blocked_force_path   seed-002-like blocked force (blocked_force.hpp, BF-1 … BF-6): the 40 mm
//                  ball slid along a rough strip (Gaussian, σ = 0.3 µm, correlation length 10 µm,
//                  4 µm cells, 384 × 384 strip, 128 × 128 moving window, H = 5 GPa, tolerance
//                  1e-10) at the fixed approach of Hertz under 2.58 N, 64 positions 8 µm apart;
//                  seconds = whole path, ratio = seconds per position, stiffness included
//   blocked_force_load   the same path at the approach whose mean force is 2.58 N (BF-3, BF-4');
//                  ratio = seconds per contact solve
//
//   side_iteration  CG iteration at grid sides 510, 511, 512 (padding README Eq. 3); ratio = vs 512
//   hertz_iterations  cold Hertz solves at 256², 512², 1024²: line-search start vs coarse start
//                  (README Eq. 16), plain vs preconditioned CG (Eq. 7b), fine and coarse-grid iterations
//
// Times: cg_iteration and convolution are thread CPU seconds on one thread (min of 5 interleaved
// trials for the ratio), *_wall the same on all threads; hertz_*, seed_table are wall seconds on
// OMP_NUM_THREADS threads.
// Usage: bench_contact [--quick | --hertz | --path | --sides]   (--quick: 256² and 512² only, 3 realisations;
//                                             --hertz: hertz_solve and hertz_stiffness only;
//                                             --path: path_table_build (wall on all threads) and
//                                             path_table_interpolation (vs direct solves) only)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <random>
#include <vector>

#include <fftw3.h>

#include "kernels/beam/path_contact_table.hpp"
#include "kernels/contact/blocked_force.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/half_space_operator.hpp"
#include "kernels/contact/path_table.hpp"
#include "kernels/contact/sweep.hpp"
#include "kernels/spectral/fftw_handles.hpp"

using namespace rollspec::contact;

namespace {
constexpr double kPi = 3.14159265358979323846;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
// CPU time of the calling thread: robust against other jobs on a shared machine.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Gaussian rough surface: white noise (std::mt19937, Box–Muller by hand — bench code only, the
// engine draws from Philox) filtered by a Gaussian in q, then scaled to zero mean and std sigma.
std::vector<double> rough_surface(std::size_t n, double dx, double sigma, double corr_length, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const std::size_t nc = n / 2 + 1;
  const rollspec::spectral::RealBuffer real(n * n);
  const rollspec::spectral::ComplexBuffer spec(n * nc);
  for (std::size_t i = 0; i < n * n; i += 2) {
    const double u1 = 1.0 - uni(gen), u2 = uni(gen);
    const double r = std::sqrt(-2.0 * std::log(u1));
    real[i] = r * std::cos(2 * kPi * u2);
    if (i + 1 < n * n) real[i + 1] = r * std::sin(2 * kPi * u2);
  }
  const rollspec::spectral::FftwPlan fwd(
      [&] { return fftw_plan_dft_r2c_2d(int(n), int(n), real.data(), spec.data(), FFTW_ESTIMATE); },
      "bench surface r2c");
  const rollspec::spectral::FftwPlan bwd(
      [&] { return fftw_plan_dft_c2r_2d(int(n), int(n), spec.data(), real.data(), FFTW_ESTIMATE); },
      "bench surface c2r");
  fftw_execute(fwd.get());
  const double len = double(n) * dx;
  for (std::size_t r = 0; r < n; ++r) {
    const double my = r <= n / 2 ? double(r) : double(r) - double(n);
    for (std::size_t c = 0; c < nc; ++c) {
      const double qx = 2 * kPi * double(c) / len, qy = 2 * kPi * my / len;
      const double f = std::exp(-(qx * qx + qy * qy) * corr_length * corr_length / 8.0);
      spec[r * nc + c][0] *= f;
      spec[r * nc + c][1] *= f;
    }
  }
  fftw_execute(bwd.get());
  std::vector<double> h(real.data(), real.data() + n * n);
  double mean = 0.0, var = 0.0;
  for (double v : h) mean += v / double(h.size());
  for (double v : h) var += (v - mean) * (v - mean) / double(h.size());
  for (double& v : h) v = (v - mean) * sigma / std::sqrt(var);
  return h;
}

void bench_iteration(std::size_t n) {
  const double e_star = 115.4e9, radius = 0.02;
  // Smooth ball, contact radius ≈ 0.3 of the half-width: realistic set sizes.
  const double a = 69e-6, dx = a / (0.3 * double(n) / 2);
  const Grid grid{n, n, dx, dx};
  // Thread CPU time counts only this thread: the ratio is measured on one thread.
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  ContactSolver solver(grid, e_star, Boundary::Open, PlannerEffort::Measure);
  const auto gap = ball_gap(grid, radius, {});
  const double w = a * a / radius;
  // Two convolutions of the padded size vs one CG iteration, interleaved five times, minimum of
  // each (thread CPU time): the ratio compares like with like on a busy machine.
  std::vector<double> p(grid.size(), 0.0), u(grid.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = gap[i] < w ? 1e9 : 0.0;
  HalfSpaceOperator& op = solver.half_space();
  op.apply(p.data(), u.data());
  // CG iterations: a fixed count (tolerance 0), no stiffness; the start-up and final products are
  // included, so the per-iteration time is an upper bound.
  SolverOptions opt;
  opt.tolerance = 0.0;
  opt.max_iterations = n >= 1024 ? 20 : 60;
  opt.compute_stiffness = false;
  opt.coarse_start = false;
  const int reps = n >= 1024 ? 10 : 40;
  double t_conv = 1e300, t_iter = 1e300;
  ContactResult r;
  for (int trial = 0; trial < 5; ++trial) {
    double t0 = thread_cpu_seconds();
    for (int k = 0; k < reps; ++k) op.apply(p.data(), u.data());
    t_conv = std::min(t_conv, (thread_cpu_seconds() - t0) / reps);
    std::vector<double> pc;
    t0 = thread_cpu_seconds();
    r = solver.solve(gap, w, pc, opt);
    t_iter = std::min(t_iter, (thread_cpu_seconds() - t0) / r.iterations);
  }
  std::printf("convolution,%zu,%.6e,,,padded %zux%zu r2c/c2r\n", n, t_conv, op.fft_nx(), op.fft_ny());
  std::printf("cg_iteration,%zu,%.6e,%.3f,%d,ratio = iteration / (2 convolutions) on 1 thread\n", n, t_iter,
              t_iter / (2 * t_conv), r.iterations);
  // The same on all threads, wall time.
  omp_set_num_threads(threads);
  double w_conv = 1e300, w_iter = 1e300;
  for (int trial = 0; trial < 5; ++trial) {
    auto t0 = Clock::now();
    for (int k = 0; k < reps; ++k) op.apply(p.data(), u.data());
    w_conv = std::min(w_conv, seconds_since(t0) / reps);
    std::vector<double> pc;
    t0 = Clock::now();
    r = solver.solve(gap, w, pc, opt);
    w_iter = std::min(w_iter, seconds_since(t0) / r.iterations);
  }
  std::printf("convolution_wall,%zu,%.6e,%.3f,,wall seconds on %d threads (ratio = vs 1 thread CPU)\n", n, w_conv,
              w_conv / t_conv, threads);
  std::printf("cg_iteration_wall,%zu,%.6e,%.3f,%d,ratio = iteration / (2 convolutions), wall on %d threads\n", n,
              w_iter, w_iter / (2 * w_conv), r.iterations, threads);
  std::fflush(stdout);
}

// Per-iteration cost of the grid sides 510, 511, 512 (README Eq. 3: each axis padded to
// fast_fft_length(2n − 1)): thread CPU seconds per CG iteration on one thread, FFTW_ESTIMATE plans
// as the tables use them, minimum of 5 interleaved trials; ratio = against side 512. Two contacts:
// `side_iteration`, 77 cells per contact radius (the products run on the box of README Eq. 3c, a
// padded 512²), and `side_iteration_full`, 0.42 n cells per radius (the box is the whole grid: every
// product on the padded grid, 1024² for all three sides; 2n padding would be 1020² and 1022²).
void bench_sides() {
  const double e_star = 115.4e9, radius = 0.02, a = 69e-6;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::size_t sides[] = {510, 511, 512};
  for (const bool full : {false, true}) {
    std::vector<std::unique_ptr<ContactSolver>> solvers;
    std::vector<std::vector<double>> gaps;
    for (std::size_t n : sides) {
      const double dx = full ? a / (0.42 * static_cast<double>(n)) : a / (0.3 * 512.0 / 2);
      solvers.push_back(std::make_unique<ContactSolver>(Grid{n, n, dx, dx}, e_star));
      gaps.push_back(ball_gap(Grid{n, n, dx, dx}, radius, {}));
    }
    SolverOptions opt;
    opt.tolerance = 0.0;
    opt.max_iterations = 30;
    opt.compute_stiffness = false;
    opt.coarse_start = false;
    double best[3] = {1e300, 1e300, 1e300};
    int iterations[3] = {0, 0, 0};
    for (int trial = 0; trial < 5; ++trial)
      for (std::size_t s = 0; s < 3; ++s) {
        std::vector<double> p;
        const double t0 = thread_cpu_seconds();
        const ContactResult r = solvers[s]->solve(gaps[s], a * a / radius, p, opt);
        best[s] = std::min(best[s], (thread_cpu_seconds() - t0) / r.iterations);
        iterations[s] = r.iterations;
      }
    for (std::size_t s = 0; s < 3; ++s)
      std::printf("%s,%zu,%.6e,%.3f,%d,padded %zux%zu; ratio = vs side 512 (1 thread CPU per CG iteration)\n",
                  full ? "side_iteration_full" : "side_iteration", sides[s], best[s], best[s] / best[2], iterations[s],
                  solvers[s]->half_space().fft_nx(), solvers[s]->half_space().fft_ny());
  }
  omp_set_num_threads(threads);
  std::fflush(stdout);
}

// Cold Hertz solve at n² (ball centre on a cell corner, 0.3 n/2 cells per contact radius), with the
// coarse start of README Eq. 16 or the line-search start: wall and CPU seconds, iterations.
ContactResult hertz_cold(std::size_t n, bool coarse, double& wall, double& cpu, double& t_plan,
                         bool precondition = true) {
  const double e_star = 115.4e9, radius = 0.02, w = 0.241e-6;
  const double a = std::sqrt(radius * w), dx = a / (0.3 * double(n) / 2);
  const Grid grid{n, n, dx, dx};
  double t0 = thread_cpu_seconds();
  ContactSolver solver(grid, e_star, Boundary::Open, PlannerEffort::Measure);
  t_plan = thread_cpu_seconds() - t0;
  const auto gap = ball_gap(grid, radius, {}, BallShape::Paraboloid);
  SolverOptions opt;
  opt.tolerance = 1e-10;
  opt.compute_stiffness = false;
  opt.coarse_start = coarse;
  opt.precondition = precondition;
  std::vector<double> p;
  if (coarse) {  // the coarse solvers' plans are made on first use: not part of the solve
    std::vector<double> q;
    SolverOptions o = opt;
    o.max_iterations = 0;
    solver.solve(gap, w, q, o);
  }
  const auto w0 = Clock::now();
  const std::clock_t c0 = std::clock();
  const ContactResult r = solver.solve(gap, w, p, opt);
  wall = seconds_since(w0);
  cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

// Iterations of the cold solve at each n: line-search start vs coarse start (README Eq. 16), plain
// vs preconditioned CG (Eq. 7b).
void bench_hertz_iterations(bool quick) {
  for (std::size_t n : {256u, 512u, 1024u}) {
    if (quick && n > 512) continue;
    for (bool precondition : {false, true})
      for (bool coarse : {false, true}) {
        double wall = 0, cpu = 0, plan = 0;
        const ContactResult r = hertz_cold(n, coarse, wall, cpu, plan, precondition);
        std::printf(
            "hertz_iterations,%zu,%.4f,%.3f,%d,%s start %s CG: %d fine + %d coarse-grid iterations (ratio = CPU s; "
            "wall in seconds; threads=%d)\n",
            n, wall, cpu, r.iterations, coarse ? "coarse" : "line-search", precondition ? "preconditioned" : "plain",
            r.iterations, r.coarse_iterations, omp_get_max_threads());
        std::fflush(stdout);
      }
  }
}

void bench_hertz_solve() {
  const std::size_t n = 512;
  const double e_star = 115.4e9, radius = 0.02, w = 0.241e-6;
  const double a = std::sqrt(radius * w);
  double wall = 0, cpu = 0, t_plan = 0;
  hertz_cold(n, true, wall, cpu, t_plan);  // warm-up: FFTW wisdom, page faults
  const ContactResult r = hertz_cold(n, true, wall, cpu, t_plan);
  const double force = 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(w, 1.5);
  std::printf(
      "hertz_solve,%zu,%.4f,%.3e,%d,wall seconds on %d threads; cold (coarse) start to 1e-10 converged=%d +%d "
      "coarse-grid iterations; %.2f s CPU (+%.2f s FFTW_MEASURE planning; %.1f cells/a)\n",
      n, wall, r.force / force - 1.0, r.iterations, omp_get_max_threads(), int(r.converged), r.coarse_iterations, cpu,
      t_plan, 0.3 * double(n) / 2);
  // Frozen-set stiffness on the converged field (warm start: 0 contact iterations).
  const Grid grid{n, n, a / (0.3 * double(n) / 2), a / (0.3 * double(n) / 2)};
  ContactSolver solver(grid, e_star, Boundary::Open, PlannerEffort::Measure);
  const auto gap = ball_gap(grid, radius, {}, BallShape::Paraboloid);
  SolverOptions opt;
  opt.tolerance = 1e-10;
  std::vector<double> p;
  opt.compute_stiffness = false;
  solver.solve(gap, w, p, opt);
  opt.compute_stiffness = true;
  const auto t0 = Clock::now();
  const ContactResult rk = solver.solve(gap, w, p, opt);
  const double tk = seconds_since(t0);
  std::printf(
      "hertz_stiffness,%zu,%.4f,%.3e,%d,wall seconds; frozen-set CG to 1e-12 + sub-cell edge (ratio = k / 2E*a - 1; "
      "frozen set alone %.3e)\n",
      n, tk, rk.stiffness / (2 * e_star * a) - 1.0, rk.stiffness_iterations,
      rk.frozen_stiffness / (2 * e_star * a) - 1.0);
  std::fflush(stdout);
}

void bench_seed_table(int realisations) {
  const std::size_t n = 256, steps = 20;
  const double e_star = 115.4e9, radius = 0.02, hardness = 5e9, sigma = 0.3e-6, corr = 10e-6;
  const double dx = 2e-6;  // 512 µm square
  const Grid grid{n, n, dx, dx};
  std::vector<std::vector<ContactResult>> results(static_cast<std::size_t>(realisations));
  int failures = 0;
  long iterations = 0;
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
#pragma omp parallel reduction(+ : failures, iterations)
  {
    ContactSolver solver(grid, e_star);  // one solver (plans, buffers) per thread
#pragma omp for schedule(dynamic)
    for (int k = 0; k < realisations; ++k) {
      const auto h = rough_surface(n, dx, sigma, corr, 1000u + unsigned(k));
      const auto gap = ball_gap(grid, radius, h);
      const double first = *std::min_element(gap.begin(), gap.end());
      std::vector<double> approaches;
      for (std::size_t j = 1; j <= steps; ++j) approaches.push_back(first + 0.05e-6 * double(j));  // to 1 µm
      SolverOptions opt;
      opt.hardness = hardness;
      opt.tolerance = 1e-8;
      auto& res = results[static_cast<std::size_t>(k)];
      res = sweep(solver, gap, approaches, opt);
      for (const auto& r : res) {
        failures += r.converged ? 0 : 1;
        iterations += r.iterations;
      }
    }
  }
  const double t = seconds_since(t0);
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  // Mean force and stiffness per step; k near the ball weight 2.58 N vs smooth Hertz at that force.
  double best = 1e300, k_ratio = 0.0, f_at = 0.0;
  for (std::size_t j = 0; j < steps; ++j) {
    double f = 0.0, k = 0.0;
    for (const auto& res : results) {
      f += res[j].force / realisations;
      k += res[j].stiffness / realisations;
    }
    if (std::fabs(f - 2.58) < best) {
      best = std::fabs(f - 2.58);
      const double a_h = std::cbrt(3.0 * f * radius / (4.0 * e_star));
      k_ratio = k / (2 * e_star * a_h);
      f_at = f;
    }
  }
  std::printf(
      "seed_table,%zu,%.3f,%.3f,%ld,%d realisations x %zu steps threads=%d (wall time; %.1f s CPU) unconverged=%d mean "
      "force at that step %.3g N\n",
      n, t, k_ratio, iterations, realisations, steps, omp_get_max_threads(), cpu, failures, f_at);
  std::fflush(stdout);
}
void bench_blocked_force() {
  const std::size_t n_strip = 384, n_window = 128, count = 64;
  const double e_star = 115.4e9, radius = 0.02, hardness = 5e9, sigma = 0.3e-6, corr = 10e-6, dx = 4e-6, load = 2.58;
  const Grid strip{n_strip, n_strip, dx, dx}, window{n_window, n_window, dx, dx};
  const auto heights = rough_surface(n_strip, dx, sigma, corr, 2002u);
  std::vector<double> x(count);
  for (std::size_t k = 0; k < count; ++k) x[k] = (static_cast<double>(k) - 0.5 * static_cast<double>(count)) * 2.0 * dx;
  ContactSolver solver(window, e_star, Boundary::Open, PlannerEffort::Measure);
  SolverOptions opt;
  opt.hardness = hardness;
  opt.tolerance = 1e-10;
  // BF-4: the smooth Hertz approach for the load.
  const double d = std::pow(3.0 * load / (4.0 * e_star * std::sqrt(radius)), 2.0 / 3.0);
  double t0 = thread_cpu_seconds();
  const BlockedForcePath path = blocked_force_path(solver, strip, heights, radius, BallShape::Sphere, x, d, opt);
  const double t = thread_cpu_seconds() - t0;
  std::printf(
      "blocked_force_path,%zu,%.4f,%.4e,%d,%zu positions at d = %.4g um window %zux%zu (ratio = s per position; +%d "
      "stiffness iterations) converged=%d mean F0 %.4g N k0 %.4g N/m (frozen set %.4g)\n",
      n_window, t, t / double(count), path.iterations, count, d * 1e6, n_window, n_window, path.stiffness_iterations,
      int(path.converged), path.mean_force, path.k0, path.k0_frozen);
  std::fflush(stdout);
  t0 = thread_cpu_seconds();
  const BlockedForcePath at = blocked_force_at_load(solver, strip, heights, radius, BallShape::Sphere, x, load, opt);
  const double tl = thread_cpu_seconds() - t0;
  std::printf(
      "blocked_force_load,%zu,%.4f,%.4e,%d,W = %.3g N: %d paths + %d pre-search paths %d solves (ratio = s per solve; "
      "+%d stiffness iterations) converged=%d d0 = %.4g um k0 %.4g N/m\n",
      n_window, tl, tl / double(at.solves), at.iterations, load, at.paths, at.presearch_paths, at.solves,
      at.stiffness_iterations, int(at.converged), at.approach * 1e6, at.k0);
  std::fflush(stdout);
}
// Path table (kernels/beam README B41-B45) on the seed-like strip of bench_blocked_force: build wall
// time on the threads given, and the interpolated P (B44-B45) against direct whole-strip solves at
// approaches mid-way between the tabulated ones and positions mid-way between tabulated ones.
void bench_path_table() {
  const std::size_t n_strip = 384, n_window = 200, count = 32, step = 2;  // 8 um steps: a/8.7
  const double e_star = 115.4e9, radius = 0.02, hardness = 5e9, sigma = 0.3e-6, corr = 10e-6, dx = 4e-6, load = 2.58;
  const Grid strip{n_strip, n_strip, dx, dx}, window{n_window, n_window, dx, dx};
  const auto heights = rough_surface(n_strip, dx, sigma, corr, 2002u);
  std::vector<double> x(count);
  for (std::size_t k = 0; k < count; ++k) x[k] = strip.x(n_strip / 2 - count * step / 2 + k * step);
  SolverOptions opt;
  opt.hardness = hardness;
  opt.tolerance = 1e-10;
  const auto t0 = Clock::now();
  const PathTable t = build_path_table(window, e_star, strip, heights, radius, BallShape::Sphere, x, load, opt);
  const double wall = seconds_since(t0);
  std::printf(
      "path_table_build,%zu,%.4f,%.4e,%d,%zu approaches x %zu positions window %zu (ratio = wall s per solve) "
      "converged=%d delta %.4g..%.4g um\n",
      n_window, wall, wall / double(t.solves), t.iterations, t.approach.size(), count, n_window, int(t.converged),
      t.approach.front() * 1e6, t.approach.back() * 1e6);
  std::fflush(stdout);
  const rollspec::beam::PathContactTable table({t.position, t.approach, t.first_contact, t.force, {}});
  double worst_d = 0.0, worst_x = 0.0, sum_d = 0.0, sum_x = 0.0;
  int n_d = 0, n_x = 0;
  for (std::size_t j = 0; j + 1 < t.approach.size(); ++j)
    for (std::size_t k : {std::size_t{5}, std::size_t{20}}) {
      const double d = 0.5 * (t.approach[j] + t.approach[j + 1]);
      double p, s;
      table.evaluate(d, x[k], p, s);
      const double e =
          std::fabs(p - path_force_direct(strip, heights, e_star, radius, BallShape::Sphere, x[k], 0.0, d, opt)) / load;
      worst_d = std::max(worst_d, e);
      sum_d += e;
      ++n_d;
      const double xm = 0.5 * (x[k] + x[k + 1]);
      table.evaluate(t.approach[j], xm, p, s);
      const double ex = std::fabs(p - path_force_direct(strip, heights, e_star, radius, BallShape::Sphere, xm, 0.0,
                                                        t.approach[j], opt)) /
                        load;
      worst_x = std::max(worst_x, ex);
      sum_x += ex;
      ++n_x;
    }
  std::printf(
      "path_table_interpolation,%zu,%.4f,%.4e,0,|P_interp - P_direct| / W mid-way in delta: worst %.3g mean %.3g; "
      "mid-way in xi (a/17): worst %.3g mean %.3g\n",
      n_strip, seconds_since(t0) - wall, worst_d, worst_d, sum_d / n_d, worst_x, sum_x / n_x);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const bool hertz_only = argc > 1 && std::strcmp(argv[1], "--hertz") == 0;
  std::printf("case,n,seconds,ratio,iterations,note\n");
  if (hertz_only) {
    bench_hertz_solve();
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--sides") == 0) {
    bench_sides();
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--path") == 0) {
    bench_path_table();
    return 0;
  }
  for (std::size_t n : {256u, 512u, 1024u}) {
    if (quick && n > 512) continue;
    bench_iteration(n);
  }
  bench_hertz_solve();
  bench_hertz_iterations(quick);
  bench_blocked_force();
  bench_seed_table(quick ? 3 : 10);
  return 0;
}
