#include "kernels/contact/path_runner.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

#include "kernels/contact/chunk_loop.hpp"

namespace rollspec::contact::detail {

BlockedForcePath PathRunner::run(double d, const SolverOptions& opt, const PathFields* previous, PathFields* store,
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
      if (previous != nullptr && k < previous->pressure.size() && !previous->pressure[k].empty()) {
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
      if (store != nullptr && k < store_count && k % store_stride_ == 0) {
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

void accumulate(BlockedForcePath& total, const BlockedForcePath& path) {
  total.paths += path.paths;
  total.solves += path.solves;
  total.iterations += path.iterations;
  total.stiffness_iterations += path.stiffness_iterations;
}

}  // namespace rollspec::contact::detail
