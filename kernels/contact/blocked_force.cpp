#include "kernels/contact/blocked_force.hpp"

#include "kernels/contact/hertz.hpp"
#include "kernels/contact/path_runner.hpp"

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

using detail::accumulate;
using detail::PathFields;
using detail::PathRunner;

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("blocked_force: " + what); }

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
                        BlockedForcePath& total, const std::function<void(const BlockedForcePath&, double)>& on_path,
                        PathFields* last_fields = nullptr) {
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
      if (last_fields != nullptr) *last_fields = std::move(previous);
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

// The positions BF-9 may check: every `finest`-th (their loose fields are kept), checked coarse to fine
// from every `first`-th (both powers of two times finest).
struct CheckPlan {
  std::size_t first = 0, finest = 0;
  std::function<std::unique_ptr<PathRunner>(const std::vector<double>&)> runner;  // a runner on given positions
  std::function<void(const BlockedForcePath&, std::size_t, double)> on_check;     // BlockedForceOptions::on_check
};

// BF-9: positions solved again to the full tolerance at d1 = d + δd, each started from the loose path's field
// moved along its rate (BF-6'), every `first`-th first, then halving the stride while k0's standard error is
// above check_k0_tolerance (BF-9a) and a finer level is kept. k0 by the control variate over the checked set J,
//     k0 = K̄_loose(d) + mean_J [k(x_j; d1) − k_loose(x_j; d)],   s.e. = s_Δ / √M · √(1 − M/N)     (BF-9a)
// every k scaled by k0 / K̄_loose, and the residuals r_j = F0(x_j; d1) − F0_first-order(x_j) kept: the
// error of the tabulated F0 measured where it was checked (their mean, r̄, is the mean force's offset
// from W at d1, i.e. an approach error r̄ / k0).                                               (BF-9b)
double check_positions(const CheckPlan& plan, const PathFields& fields, const SolverOptions& opt, double tolerance,
                       double step, BlockedForcePath& path, BlockedForcePath& total) {
  const std::size_t n = path.force.size();
  std::vector<std::size_t> index;
  std::vector<double> tight_force, tight_k, tight_kf;
  for (std::size_t stride = plan.first;; stride /= 2) {
    // This level's new positions: every stride-th not checked on a coarser level.
    std::vector<std::size_t> level;
    for (std::size_t k = 0; k < n; k += stride)
      if (stride == plan.first || k % (2 * stride) != 0) level.push_back(k);
    std::vector<double> x;
    PathFields start;
    start.approach = fields.approach;
    for (std::size_t k : level) {
      x.push_back(path.position[k]);
      start.pressure.push_back(k < fields.pressure.size() ? fields.pressure[k] : std::vector<double>{});
      start.rate.push_back(k < fields.rate.size() ? fields.rate[k] : std::vector<double>{});
    }
    if (x.empty()) break;
    const std::unique_ptr<PathRunner> runner = plan.runner(x);
    const BlockedForcePath tight = runner->run(fields.approach + step, opt, &start, nullptr, 0);
    accumulate(total, tight);
    if (!tight.converged) {
      path.converged = false;
      return 0.0;
    }
    for (std::size_t j = 0; j < level.size(); ++j) {
      index.push_back(level[j]);
      tight_force.push_back(tight.force[j]);
      tight_k.push_back(tight.stiffness[j]);
      tight_kf.push_back(tight.frozen_stiffness[j]);
    }
    // BF-9a over every position checked so far.
    const std::size_t m = index.size();
    double dk_sum = 0.0;
    for (std::size_t j = 0; j < m; ++j) dk_sum += tight_k[j] - path.stiffness[index[j]];
    const double mean_dk = dk_sum / static_cast<double>(m);
    double ss = 0.0;
    for (std::size_t j = 0; j < m; ++j) ss += std::pow(tight_k[j] - path.stiffness[index[j]] - mean_dk, 2);
    const double fpc = std::max(0.0, 1.0 - static_cast<double>(m) / static_cast<double>(n));
    path.k0_error = m > 1 ? std::sqrt(ss / static_cast<double>(m - 1) / static_cast<double>(m) * fpc)
                          : std::numeric_limits<double>::quiet_NaN();
    if (plan.on_check) plan.on_check(tight, stride, path.k0_error / (path.k0 + mean_dk));
    if (!(path.k0_error > tolerance * (path.k0 + mean_dk)) || stride <= plan.finest || stride < 2) break;
  }
  // In position order: the residuals and the checked k's mean do not depend on the levels' order.
  std::vector<std::size_t> order(index.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return index[a] < index[b]; });
  const std::size_t m = index.size();
  double dk_sum = 0.0, dkf_sum = 0.0;
  path.check_index.resize(m);
  path.check_residual.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = order[i], k = index[j];
    path.check_index[i] = k;
    path.check_residual[i] = tight_force[j] - path.force[k];
    dk_sum += tight_k[j] - path.stiffness[k];
    dkf_sum += tight_kf[j] - path.frozen_stiffness[k];
  }
  const double k1 = path.k0 + dk_sum / static_cast<double>(m), k1f = path.k0_frozen + dkf_sum / static_cast<double>(m);
  // BF-9d: the checks' mean residual r̄ is the mean force's offset from W at d1; a second step
  // δd2 = −r̄ / k0 puts the table on W, k moved along the slope the checks saw over the first step,
  // (K̄(d1) − K̄_loose(d)) / δd, and F0 by δd2 k + r̄ (its mean W; the residuals kept about their mean).
  double r_mean = 0.0;
  for (double r : path.check_residual) r_mean += r / static_cast<double>(m);
  const double step2 = -r_mean / k1;
  const double slope = step != 0.0 ? (k1 - path.k0) / step / k1 : 0.0;
  const double k_factor = 1.0 + step2 * slope;
  const double scale = k1 / path.k0 * k_factor, scale_f = k1f / path.k0_frozen * k_factor;
  for (std::size_t k = 0; k < n; ++k) {
    path.stiffness[k] *= scale;
    path.frozen_stiffness[k] *= scale_f;
    path.force[k] += step2 * path.stiffness[k] / k_factor + r_mean;
  }
  for (double& r : path.check_residual) r -= r_mean;
  path.k0_step = scale - 1.0;
  path.k0 = k1 * k_factor;
  path.k0_frozen = k1f * k_factor;
  path.k0_error *= k_factor;
  return step2;
}

// BF-8: one path at d (solves to the answer's tolerance, cold per chunk), moved onto the load W to
// first order along the edge-corrected stiffness, with each F0's error bound.
BlockedForcePath one_path(PathRunner& runner, const SolverOptions& opt, double load, double d, double step0,
                          const BlockedForceOptions& popt, std::size_t store_count, double presearch_slope,
                          BlockedForcePath& total, const CheckPlan* check) {
  std::size_t limiting = 0;
  const double d_cap = runner.max_approach(&limiting);
  SolverOptions loose = opt;
  loose.tolerance = std::max(opt.tolerance, popt.answer_tolerance);
  loose.stiffness_tolerance = std::max(opt.stiffness_tolerance, popt.answer_tolerance);
  // Paths (usually one: the pre-search's root) until the mean is within answer_load_tolerance of W.
  SlopePoints points;
  PathFields fields;
  if (check != nullptr) runner.set_store_stride(check->finest);
  BlockedForcePath path =
      search(runner, loose, load, popt.answer_load_tolerance, popt.max_paths, popt.warm_start != PathWarmStart::Cold,
             check != nullptr ? runner.positions() : store_count, d, step0, 0.0, total,
             points.recorder(loose.tolerance, popt.on_path), check != nullptr ? &fields : nullptr);
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
  if (check != nullptr) {
    const double step2 = check_positions(*check, fields, opt, popt.check_k0_tolerance, step, path, total);
    path.load_step = step + step2;
    path.approach += step + step2;
    double sum = 0.0;
    for (double f : path.force) sum += f;
    path.mean_force = sum / static_cast<double>(path.force.size());
    return path;
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
    // Its root is off the whole path's by its sampling error (~1e-2 on the seed 002 rig): the answer's
    // path (BF-8, BF-9) stops it at 1e-3, the exhaustive search at 1e-6.
    const double presearch_tolerance = path_options.answer_tolerance > 0.0 ? 1e-3 : 1e-6;
    BlockedForceOptions sub_options = path_options;
    if (sub_options.chunk_positions > 0) sub_options.chunk_positions = (subset.size() + 3) / 4;
    PathRunner sub_runner(solver, strip, strip_heights, radius, shape, subset, sub_options);
    const BlockedForcePath sub =
        search(sub_runner, opt, load, std::max(presearch_tolerance, path_options.load_tolerance),
               path_options.max_paths, warm, store_count(subset.size()), d_hertz, d_hertz, path_options.cold_tolerance,
               total, presearch_points.recorder(opt.tolerance, path_options.on_path));
    total.presearch_paths = total.paths;
    total.paths = 0;
    if (sub.converged) d_start = sub.approach;
  }
  // BF-9: the check levels, from every first-th position down to every finest-th. first is check_stride, or
  // on a strip too long for that many loose fields in max_stored_bytes the smallest power-of-two multiple of
  // it that fits (a long strip is checked more sparsely, not left unchecked); finest the smallest power-of-two
  // fraction of first whose fields fit.
  std::unique_ptr<CheckPlan> check;
  if (path_options.answer_tolerance > 0.0 && path_options.check_stride > 0 &&
      positions.size() >= 2 * path_options.check_stride) {
    check = std::make_unique<CheckPlan>();
    const std::size_t fit = std::max<std::size_t>(1, path_options.max_stored_bytes / field_bytes);
    const auto count = [&](std::size_t stride) { return (positions.size() + stride - 1) / stride; };
    check->first = path_options.check_stride;
    while (count(check->first) > fit) check->first *= 2;
    check->finest = check->first;
    while (check->finest % 2 == 0 && count(check->finest / 2) <= fit) check->finest /= 2;
    if (count(check->first) < 2) check.reset();  // fewer than two checks: BF-8 alone
  }
  if (check) {
    check->on_check = path_options.on_check;
    check->runner = [&, path_options](const std::vector<double>& x) {
      BlockedForceOptions o = path_options;
      o.on_chunk = nullptr;  // a level of checks reports through on_check
      // Each check position starts from its own loose field: four fixed chunks (BF-6c), the same bits on any count.
      o.chunk_positions = (x.size() + 3) / 4;
      return std::make_unique<PathRunner>(solver, strip, strip_heights, radius, shape, x, o);
    };
  }
  BlockedForcePath path =
      path_options.answer_tolerance > 0.0
          ? one_path(runner, opt, load, d_start, d_hertz, path_options, store_count(positions.size()),
                     presearch_points.relative_slope(), total, check.get())
          : search(runner, opt, load, path_options.load_tolerance, path_options.max_paths, warm,
                   store_count(positions.size()), d_start, d_hertz, path_options.cold_tolerance, total,
                   path_options.on_path);
  path.paths = total.paths;
  path.presearch_paths = total.presearch_paths;
  path.solves = total.solves;
  path.iterations = total.iterations;
  path.stiffness_iterations = total.stiffness_iterations;
  return path;
}

}  // namespace rollspec::contact
