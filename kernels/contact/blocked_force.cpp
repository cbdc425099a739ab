#include "kernels/contact/blocked_force.hpp"

#include "kernels/contact/chunk_loop.hpp"
#include "kernels/contact/hertz.hpp"
#include "kernels/contact/path_window.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace rollspec::contact {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("blocked_force: " + what); }

// Converged fields of one path (window arrays) and their rates dp/dd, for the next load-search path.
struct PathFields {
  double approach = 0.0;
  std::vector<std::vector<double>> pressure, rate;
};

// Validated path set-up (PathWindow: window placement, BF-5, BF-6) and one path at a given approach.
class PathRunner {
 public:
  PathRunner(ContactSolver& solver, const Grid& strip, const std::vector<double>& heights, double radius,
             BallShape shape, const std::vector<double>& positions, const BlockedForceOptions& path_options)
      : solver_(solver),
        window_(checked_window(solver), strip, heights, radius, shape, positions, path_options.centre_y,
                "blocked_force"),
        positions_(positions),
        popt_(path_options) {}

  double max_approach(std::size_t* position) const { return window_.max_approach(position); }
  // ε (README Eq. 9) of each solve of the last path run.
  const std::vector<double>& solve_error() const { return solve_error_; }
  [[noreturn]] void reject(std::size_t k, double d, const char* prefix = "") const { window_.reject(k, d, prefix); }

  // One path at approach d (BF-2). `previous` (optional): the fields of an earlier path, used as
  // starts for its positions (BF-6'); `store` (optional) receives the first
  // `store_count` fields of this path and their frozen-set rates dp/dd.
  BlockedForcePath run(double d, const SolverOptions& opt, const PathFields* previous, PathFields* store,
                       std::size_t store_count) {
    const std::size_t n = solver_.grid().size();
    const std::size_t count = positions_.size();
    BlockedForcePath out;
    out.approach = d;
    out.paths = 1;
    out.position = positions_;
    out.force.resize(count);
    out.stiffness.assign(count, std::numeric_limits<double>::quiet_NaN());
    out.frozen_stiffness.assign(count, std::numeric_limits<double>::quiet_NaN());
    out.converged = true;
    for (std::size_t k = 0; k < count; ++k)
      if (d > window_.limit(k)) reject(k, d);
    if (store != nullptr) {
      store_count = std::min(store_count, count);
      store->approach = d;
      store->pressure.resize(store_count);
      store->rate.resize(store_count);
    }
    // Fixed chunks of positions (BF-6c): each chunk starts cold (or from `previous`) and warm-starts
    // along itself; the chunks run in parallel, one solver per thread. The cut depends on
    // chunk_positions alone and every position's result on its chunk alone: the same bits for any
    // thread count. The sums below run in position order after the loop.
    std::vector<ContactResult> results(count);
    solve_error_.assign(count, 0.0);
    const auto run_chunk = [&](ContactSolver& s, std::size_t k0, std::size_t k1) {
      std::vector<double> p;
      for (std::size_t k = k0; k < k1; ++k) {
        const std::vector<double> gap = window_.gap(k);
        if (previous != nullptr && k < previous->pressure.size()) {
          // BF-6': p_start = p(x_k; d_prev) + (d − d_prev) dp/dd (the solver clips to [0, H]).
          const std::vector<double>& pk = previous->pressure[k];
          const std::vector<double>& rk = previous->rate[k];
          const double dd = d - previous->approach;
          p = pk;
          if (rk.size() == n)
            for (std::size_t i = 0; i < n; ++i) p[i] += dd * rk[i];
        } else if (k == k0 || popt_.warm_start == PathWarmStart::Cold) {
          p.assign(n, 0.0);
        } else {
          // BF-6: the previous field shifted with the ball (or kept on the strip).
          window_.shift_field(p,
                              popt_.warm_start == PathWarmStart::Ball ? window_.ball_shift(k) : window_.strip_shift(k));
        }
        // Eq. 11a: the frozen-set CG starts from the same position's rate on the previous path.
        const bool rate_start = previous != nullptr && k < previous->rate.size() && previous->rate[k].size() == n;
        s.set_rate_start(rate_start ? &previous->rate[k] : nullptr);
        results[k] = s.solve(gap, d, p, opt);
        s.set_rate_start(nullptr);
        if (store != nullptr && k < store_count) {
          store->pressure[k] = p;
          if (results[k].converged && opt.compute_stiffness)
            store->rate[k] = s.pressure_rate();
          else
            store->rate[k].clear();
        }
      }
      if (popt_.on_chunk) {
#pragma omp critical(blocked_force_progress)
        popt_.on_chunk(k1 - k0, count);
      }
    };
    const std::size_t chunk = popt_.chunk_positions == 0 ? count : std::min(count, popt_.chunk_positions);
    const std::size_t chunks = (count + chunk - 1) / chunk;
    const int threads = chunks > 1 ? std::min<int>(omp_get_max_threads(), static_cast<int>(chunks)) : 1;
    if (threads <= 1) {
      for (std::size_t c = 0; c < chunks; ++c) run_chunk(solver_, c * chunk, std::min(count, (c + 1) * chunk));
    } else {
      // One solver per thread, made here (FFTW plans outside the parallel region; the planner is
      // serialised anyway, kernels/spectral/fftw_handles.hpp). A solve depends on its inputs only,
      // not on what the solver ran before. Exceptions are carried out of the region.
      while (static_cast<int>(extra_.size()) < threads - 1)
        extra_.push_back(std::make_unique<ContactSolver>(solver_.grid(), solver_.half_space().e_star()));
      detail::for_each_chunk(chunks, threads, [&](std::size_t c, int t) {
        ContactSolver& s = t == 0 ? solver_ : *extra_[static_cast<std::size_t>(t - 1)];
        const std::size_t k0 = c * chunk;
        run_chunk(s, k0, std::min(count, k0 + chunk));
      });
    }
    double force_sum = 0.0, stiffness_sum = 0.0, frozen_sum = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const ContactResult& r = results[k];
      ++out.solves;
      out.iterations += r.iterations;
      out.stiffness_iterations += r.stiffness_iterations;
      out.max_error = std::max(out.max_error, r.error);
      solve_error_[k] = r.error;
      out.converged = out.converged && r.converged && (!opt.compute_stiffness || r.stiffness_converged);
      out.force[k] = r.force;
      force_sum += r.force;
      if (opt.compute_stiffness) {
        out.stiffness[k] = r.stiffness;
        out.frozen_stiffness[k] = r.frozen_stiffness;
        stiffness_sum += r.stiffness;
        frozen_sum += r.frozen_stiffness;
      }
    }
    out.mean_force = force_sum / static_cast<double>(count);
    out.k0 =
        opt.compute_stiffness ? stiffness_sum / static_cast<double>(count) : std::numeric_limits<double>::quiet_NaN();
    out.k0_frozen =
        opt.compute_stiffness ? frozen_sum / static_cast<double>(count) : std::numeric_limits<double>::quiet_NaN();
    return out;
  }

 private:
  static const Grid& checked_window(ContactSolver& solver) {
    if (solver.half_space().boundary() != Boundary::Open)
      throw std::invalid_argument("blocked_force: the solver must use the open boundary");
    return solver.grid();
  }

  ContactSolver& solver_;
  std::vector<std::unique_ptr<ContactSolver>> extra_;  // the other threads' solvers (chunks)
  PathWindow window_;
  std::vector<double> positions_;
  BlockedForceOptions popt_;
  std::vector<double> solve_error_;
};

void accumulate(BlockedForcePath& total, const BlockedForcePath& path) {
  total.paths += path.paths;
  total.solves += path.solves;
  total.iterations += path.iterations;
  total.stiffness_iterations += path.stiffness_iterations;
}

}  // namespace

BlockedForcePath blocked_force_path(ContactSolver& solver, const Grid& strip, const std::vector<double>& strip_heights,
                                    double radius, BallShape shape, const std::vector<double>& positions,
                                    double approach, const SolverOptions& options,
                                    const BlockedForceOptions& path_options) {
  if (!std::isfinite(approach)) fail("approach must be finite");
  PathRunner runner(solver, strip, strip_heights, radius, shape, positions, path_options);
  return runner.run(approach, options, nullptr, nullptr, 0);
}

namespace {

// BF-3: safeguarded Newton on d for F̄(d) = W over `runner`'s positions, from d_start; `step` grows
// the bracket while one side is unknown. Counts go to `total`; returns the last path, converged
// only if |F̄ − W| ≤ tolerance · W.
BlockedForcePath search(PathRunner& runner, const SolverOptions& opt, double load, double tolerance, int max_paths,
                        bool warm, std::size_t store_count, double d_start, double step, double cold_tolerance,
                        BlockedForcePath& total, const std::function<void(const BlockedForcePath&, double)>& on_path) {
  // BF-5 caps the approach: the search stays at or below d_cap.
  std::size_t limiting = 0;
  const double d_cap = runner.max_approach(&limiting);
  double d = std::min(d_start, d_cap);
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  PathFields previous, current;
  for (int paths = 0;;) {
    // BF-4'': a cold path (no earlier fields to start from) only places the next Newton step.
    const bool cold = paths == 0;
    SolverOptions path_opt = opt;
    if (cold && cold_tolerance > opt.tolerance) {
      path_opt.tolerance = cold_tolerance;
      path_opt.stiffness_tolerance = std::max(opt.stiffness_tolerance, cold_tolerance);
    }
    const bool exact = path_opt.tolerance == opt.tolerance;
    BlockedForcePath path =
        runner.run(d, path_opt, paths > 0 && warm ? &previous : nullptr, warm ? &current : nullptr, store_count);
    ++paths;
    std::swap(previous, current);
    accumulate(total, path);
    const bool on_load = exact && std::fabs(path.mean_force - load) <= tolerance * load;
    if (on_path) on_path(path, std::fabs(path.mean_force - load) / load);
    // An inexact path's mean force may sit on the wrong side of W near the root: no bracket from it.
    if (exact && path.mean_force < load)
      lo = d;
    else if (exact)
      hi = d;
    const bool exhausted =
        std::isfinite(lo) && std::isfinite(hi) && hi - lo <= 1e-15 * std::max(std::fabs(hi), std::fabs(lo));
    if (!path.converged || on_load || paths >= max_paths || exhausted) {
      path.converged = path.converged && on_load;
      return path;
    }
    // Newton on F̄ with its exact slope K̄_f (BF-3).
    double next =
        path.k0_frozen > 0.0 ? d + (load - path.mean_force) / path.k0_frozen : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) {
      if (std::isfinite(lo) && std::isfinite(hi)) {
        next = 0.5 * (lo + hi);
      } else {
        next = path.mean_force < load ? d + step : d - step;
        step *= 2.0;
      }
    }
    if (next > d_cap) {
      if (d >= d_cap && exact) {
        std::ostringstream os;
        os.precision(9);
        os << "the load " << load << " N exceeds the mean force " << path.mean_force
           << " N at the largest approach the strip and solver window allow; ";
        runner.reject(limiting, next, os.str().c_str());
      }
      next = d_cap;
    }
    d = next;
  }
}

// (d, K̄) of the exact paths of one search (BF-8'): the secant of K̄ over the two farthest apart,
// relative to the last, dK̄/dd / K̄ (NaN without two distinct approaches).
struct SlopePoints {
  std::vector<double> approach, k0;
  double relative_slope() const {
    const std::size_t n = approach.size();
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    std::size_t far = 0;
    for (std::size_t j = 0; j + 1 < n; ++j)
      if (std::fabs(approach[j] - approach[n - 1]) > std::fabs(approach[far] - approach[n - 1])) far = j;
    const double dd = approach[n - 1] - approach[far];
    if (dd == 0.0 || !(k0[n - 1] > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return (k0[n - 1] - k0[far]) / dd / k0[n - 1];
  }
  // on_path that also records the paths solved to `tolerance` (a loose cold path is not).
  std::function<void(const BlockedForcePath&, double)> recorder(
      double tolerance, const std::function<void(const BlockedForcePath&, double)>& user) {
    return [this, tolerance, user](const BlockedForcePath& p, double e) {
      if (p.max_error < tolerance && std::isfinite(p.k0)) {
        approach.push_back(p.approach);
        k0.push_back(p.k0);
      }
      if (user) user(p, e);
    };
  }
};

// BF-8: one path at d (solves to the answer's tolerance, cold per chunk), moved onto the load W to
// first order along the edge-corrected stiffness, with each F0's error bound.
BlockedForcePath one_path(PathRunner& runner, const SolverOptions& opt, double load, double d, double step0,
                          const BlockedForceOptions& popt, std::size_t store_count, double presearch_slope,
                          BlockedForcePath& total) {
  std::size_t limiting = 0;
  const double d_cap = runner.max_approach(&limiting);
  SolverOptions loose = opt;
  loose.tolerance = std::max(opt.tolerance, popt.answer_tolerance);
  loose.stiffness_tolerance = std::max(opt.stiffness_tolerance, popt.answer_tolerance);
  // Paths (usually one: the pre-search's root) until the mean is within answer_load_tolerance of W.
  SlopePoints points;
  BlockedForcePath path =
      search(runner, loose, load, popt.answer_load_tolerance, popt.max_paths, popt.warm_start != PathWarmStart::Cold,
             store_count, d, step0, 0.0, total, points.recorder(loose.tolerance, popt.on_path));
  if (!path.converged || !(path.k0 > 0.0)) {
    path.converged = false;
    return path;
  }
  const double step = (load - path.mean_force) / path.k0;
  if (path.approach + step > d_cap) {
    std::ostringstream os;
    os.precision(9);
    os << "the load " << load << " N needs an approach beyond the largest the strip and solver window allow; ";
    runner.reject(limiting, path.approach + step, os.str().c_str());
  }
  const std::vector<double>& eps = runner.solve_error();
  path.force_error.resize(path.force.size());
  double force_sum = 0.0;
  for (std::size_t k = 0; k < path.force.size(); ++k) {
    path.force_error[k] =
        std::fabs(step) * std::fabs(path.stiffness[k] - path.frozen_stiffness[k]) + eps[k] * std::fabs(path.force[k]);
    path.force[k] += step * path.stiffness[k];
    force_sum += path.force[k];
  }
  // BF-8': k moves with d too (a 1e-2 load step moved k0 by 0.7 % on the seed 002 rig, the bands by
  // 0.2 dB through the contact resonance): K̄'s relative slope from this search's own paths if it
  // ran two, else from the pre-search's (another subset of positions, the same strip).
  const double slope = points.approach.size() >= 2 ? points.relative_slope() : presearch_slope;
  const double k_factor = std::isfinite(slope) ? 1.0 + step * slope : 1.0;
  for (std::size_t k = 0; k < path.force.size(); ++k) {
    path.stiffness[k] *= k_factor;
    path.frozen_stiffness[k] *= k_factor;
  }
  path.k0 *= k_factor;
  path.k0_frozen *= k_factor;
  path.k0_step = k_factor - 1.0;
  path.load_step = step;
  path.approach += step;
  path.mean_force = force_sum / static_cast<double>(path.force.size());
  return path;
}

}  // namespace

BlockedForcePath blocked_force_at_load(ContactSolver& solver, const Grid& strip,
                                       const std::vector<double>& strip_heights, double radius, BallShape shape,
                                       const std::vector<double>& positions, double load, const SolverOptions& options,
                                       const BlockedForceOptions& path_options) {
  if (!(load > 0.0) || !std::isfinite(load)) fail("load must be finite, > 0");
  if (!(path_options.load_tolerance > 0.0)) fail("load_tolerance must be > 0");
  if (!(path_options.answer_tolerance >= 0.0 && path_options.answer_tolerance < 1.0))
    fail("answer_tolerance must be in [0, 1)");
  PathRunner runner(solver, strip, strip_heights, radius, shape, positions, path_options);
  SolverOptions opt = options;
  opt.compute_stiffness = true;
  // BF-4: smooth Hertz approach for W; also the first bracket-growth step.
  const double d_hertz = hertz::approach_at_load(radius, solver.half_space().e_star(), load);
  // Fields kept between paths: all positions if they fit in max_stored_bytes, else the first.
  const bool warm = path_options.warm_start != PathWarmStart::Cold;
  const std::size_t field_bytes = 2 * sizeof(double) * solver.grid().size();
  const auto store_count = [&](std::size_t count) {
    return warm ? std::max<std::size_t>(1, std::min(count, path_options.max_stored_bytes / field_bytes)) : 0;
  };
  BlockedForcePath total;
  double d_start = d_hertz;
  SlopePoints presearch_points;
  // BF-4': pre-search on every S-th position to 1e-6, then the full path from there.
  const std::size_t m = path_options.presearch_positions;
  if (m > 0 && positions.size() >= 4 * m) {
    const std::size_t stride = positions.size() / m;
    std::vector<double> subset;
    for (std::size_t k = 0; k < positions.size(); k += stride) subset.push_back(positions[k]);
    // Its positions lie S steps apart, farther than a window: each starts cold anyway, so chunked
    // paths cut the subset in four chunks (BF-6c: on the threads, the same bits on any count).
    BlockedForceOptions sub_options = path_options;
    if (sub_options.chunk_positions > 0) sub_options.chunk_positions = (subset.size() + 3) / 4;
    PathRunner sub_runner(solver, strip, strip_heights, radius, shape, subset, sub_options);
    const BlockedForcePath sub =
        search(sub_runner, opt, load, std::max(1e-6, path_options.load_tolerance), path_options.max_paths, warm,
               store_count(subset.size()), d_hertz, d_hertz, path_options.cold_tolerance, total,
               presearch_points.recorder(opt.tolerance, path_options.on_path));
    total.presearch_paths = total.paths;
    total.paths = 0;
    if (sub.converged) d_start = sub.approach;
  }
  BlockedForcePath path = path_options.answer_tolerance > 0.0
                              ? one_path(runner, opt, load, d_start, d_hertz, path_options,
                                         store_count(positions.size()), presearch_points.relative_slope(), total)
                              : search(runner, opt, load, path_options.load_tolerance, path_options.max_paths, warm,
                                       store_count(positions.size()), d_start, d_hertz, path_options.cold_tolerance,
                                       total, path_options.on_path);
  path.paths = total.paths;
  path.presearch_paths = total.presearch_paths;
  path.solves = total.solves;
  path.iterations = total.iterations;
  path.stiffness_iterations = total.stiffness_iterations;
  return path;
}

}  // namespace rollspec::contact
