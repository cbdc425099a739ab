#include "kernels/contact/blocked_force.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace rollspec::contact {

namespace {

using Index = std::ptrdiff_t;

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("blocked_force: " + what); }

bool same(double a, double b) { return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b)); }

// z_ball(r) of README Eq. 5 (the same expressions as ball_gap).
double ball_height(double r2, double radius, BallShape shape) {
  if (shape == BallShape::Paraboloid) return r2 / (2.0 * radius);
  return r2 < radius * radius ? r2 / (radius + std::sqrt(radius * radius - r2)) : radius;
}

// Converged fields of one path (window arrays) and their rates dp/dd, for the next load-search path.
struct PathFields {
  double approach = 0.0;
  std::vector<std::vector<double>> pressure, rate;
};

// Validated path set-up: window placement j_k and rows, ball shifts σ_k (BF-6), approach limits (BF-5).
class PathRunner {
 public:
  PathRunner(ContactSolver& solver, const Grid& strip, const std::vector<double>& heights, double radius,
             BallShape shape, const std::vector<double>& positions, const BlockedForceOptions& path_options)
      : solver_(solver), strip_(strip), heights_(heights), radius_(radius), shape_(shape), positions_(positions),
        popt_(path_options) {
    check_grid(strip);
    const Grid& win = solver.grid();
    if (solver.half_space().boundary() != Boundary::Open) fail("the solver must use the open boundary");
    if (!same(win.dx, strip.dx) || !same(win.dy, strip.dy)) fail("solver grid cells differ from the strip's");
    if (win.nx > strip.nx || win.ny > strip.ny) fail("solver grid is larger than the strip");
    if (!heights.empty() && heights.size() != strip.size()) fail("strip heights size != strip grid size");
    if (!(radius > 0.0) || !std::isfinite(radius)) fail("radius must be finite, > 0");
    if (!std::isfinite(path_options.centre_y)) fail("centre_y must be finite");
    if (positions.empty()) fail("no positions");
    for (double x : positions)
      if (!std::isfinite(x)) fail("positions must be finite");

    const Index nxs = static_cast<Index>(strip.nx), nxw = static_cast<Index>(win.nx);
    const Index j_max = nxs - nxw;
    // j_0 centres the window on x_0: strip column of x_0 is x_0/dx + (nx_s − 1)/2.
    const double centre_col = positions[0] / strip.dx + 0.5 * static_cast<double>(nxs - 1) -
                              0.5 * static_cast<double>(nxw - 1);
    if (!(std::fabs(centre_col) < 1e15)) fail("position 0 is far outside the strip");
    Index j_free = static_cast<Index>(std::llround(centre_col));
    start_.resize(positions.size());
    shift_.assign(positions.size(), 0);
    start_[0] = std::clamp<Index>(j_free, 0, j_max);
    for (std::size_t k = 1; k < positions.size(); ++k) {
      const double steps = (positions[k] - positions[k - 1]) / strip.dx;
      const double m = std::round(steps);
      if (!(m >= 1.0) || std::fabs(steps - m) > 1e-6) {
        std::ostringstream os;
        os << "position step " << k << " (x = " << positions[k - 1] << " -> " << positions[k]
           << " m) is not a positive whole number of cells dx = " << strip.dx << " m";
        fail(os.str());
      }
      j_free += static_cast<Index>(m);
      start_[k] = std::clamp<Index>(j_free, 0, j_max);
      shift_[k] = static_cast<Index>(m) - (start_[k] - start_[k - 1]);
    }
    // Window rows: fixed along the path, centred on y_c.
    const Index nys = static_cast<Index>(strip.ny), nyw = static_cast<Index>(win.ny);
    const double centre_row = path_options.centre_y / strip.dy + 0.5 * static_cast<double>(nys - 1) -
                              0.5 * static_cast<double>(nyw - 1);
    if (!(std::fabs(centre_row) < 1e15)) fail("centre_y is far outside the strip");
    row0_ = static_cast<std::size_t>(std::clamp<Index>(static_cast<Index>(std::llround(centre_row)), 0, nys - nyw));
    column_max_.assign(strip.nx, 0.0);
    row_max_.assign(strip.ny, 0.0);
    if (!heights.empty()) {
      std::fill(column_max_.begin(), column_max_.end(), -std::numeric_limits<double>::infinity());
      std::fill(row_max_.begin(), row_max_.end(), -std::numeric_limits<double>::infinity());
      for (std::size_t iy = 0; iy < strip.ny; ++iy)
        for (std::size_t ix = 0; ix < strip.nx; ++ix) {
          column_max_[ix] = std::max(column_max_[ix], heights[iy * strip.nx + ix]);
          row_max_[iy] = std::max(row_max_[iy], heights[iy * strip.nx + ix]);
        }
      height_max_ = *std::max_element(column_max_.begin(), column_max_.end());
    }
    window_heights_.assign(win.size(), 0.0);
    limit_.resize(positions.size());
    limit_where_.resize(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) approach_limit(k);
  }

  // BF-5: the largest approach allowed at every position, and the position that sets it.
  double max_approach(std::size_t* position) const {
    const auto it = std::min_element(limit_.begin(), limit_.end());
    *position = static_cast<std::size_t>(it - limit_.begin());
    return *it;
  }

  [[noreturn]] void reject(std::size_t k, double d, const char* prefix = "") const {
    std::ostringstream os;
    os.precision(9);
    os << prefix << "at position " << k << " (x = " << positions_[k] << " m) the ball's rigid interference at approach " << d
       << " m reaches " << limit_where_[k] << " (allowed there: approach <= " << limit_[k] << " m)";
    fail(os.str());
  }

  // One path at approach d (BF-2). `previous` (optional): the fields of an earlier path, used as
  // starts for its positions (BF-6'); `store` (optional) receives the first
  // `store_count` fields of this path and their frozen-set rates dp/dd.
  BlockedForcePath run(double d, const SolverOptions& opt, const PathFields* previous, PathFields* store,
                       std::size_t store_count) {
    const Grid& win = solver_.grid();
    const std::size_t nxw = win.nx, ny = win.ny, n = win.size();
    const std::size_t count = positions_.size();
    BlockedForcePath out;
    out.approach = d;
    out.paths = 1;
    out.position = positions_;
    out.force.resize(count);
    out.stiffness.assign(count, std::numeric_limits<double>::quiet_NaN());
    out.converged = true;
    for (std::size_t k = 0; k < count; ++k)
      if (d > limit_[k]) reject(k, d);
    if (store != nullptr) {
      store_count = std::min(store_count, count);
      store->approach = d;
      store->pressure.resize(store_count);
      store->rate.resize(store_count);
    }
    std::vector<double> p, shifted(n);
    double force_sum = 0.0, stiffness_sum = 0.0, frozen_sum = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const Index j = start_[k];
      for (std::size_t iy = 0; iy < ny; ++iy)
        for (std::size_t ix = 0; ix < nxw; ++ix)
          window_heights_[iy * nxw + ix] =
              heights_.empty() ? 0.0 : heights_[(row0_ + iy) * strip_.nx + static_cast<std::size_t>(j) + ix];
      // Window coordinates = strip coordinates − (strip.x(j) − win.x(0), strip.y(row0) − win.y(0)).
      const double offset_x = strip_.x(static_cast<std::size_t>(j)) - win.x(0);
      const double offset_y = strip_.y(row0_) - win.y(0);
      const std::vector<double> gap = ball_gap(win, radius_, window_heights_, shape_, positions_[k] - offset_x,
                                               popt_.centre_y - offset_y);

      if (previous != nullptr && k < previous->pressure.size()) {
        // BF-6': p_start = p(x_k; d_prev) + (d − d_prev) dp/dd (the solver clips to [0, H]).
        const std::vector<double>& pk = previous->pressure[k];
        const std::vector<double>& rk = previous->rate[k];
        const double dd = d - previous->approach;
        p = pk;
        if (rk.size() == n)
          for (std::size_t i = 0; i < n; ++i) p[i] += dd * rk[i];
      } else if (k == 0) {
        p.assign(n, 0.0);
      } else if (popt_.warm_start == PathWarmStart::Cold) {
        p.assign(n, 0.0);
      } else {
        const Index s = popt_.warm_start == PathWarmStart::Ball ? shift_[k] : -(start_[k] - start_[k - 1]);
        if (s != 0) {
          // BF-6: p_start[ix] = p[ix − s] on each row, zero where ix − s leaves the window.
          const Index nx = static_cast<Index>(nxw);
          for (std::size_t iy = 0; iy < ny; ++iy)
            for (Index ix = 0; ix < nx; ++ix) {
              const Index src = ix - s;
              shifted[iy * nxw + static_cast<std::size_t>(ix)] =
                  (src >= 0 && src < nx) ? p[iy * nxw + static_cast<std::size_t>(src)] : 0.0;
            }
          p.swap(shifted);
        }
      }
      const ContactResult r = solver_.solve(gap, d, p, opt);
      if (store != nullptr && k < store_count) {
        store->pressure[k] = p;
        if (r.converged && opt.compute_stiffness) store->rate[k] = solver_.pressure_rate();
        else store->rate[k].clear();
      }
      ++out.solves;
      out.iterations += r.iterations;
      out.stiffness_iterations += r.stiffness_iterations;
      out.max_error = std::max(out.max_error, r.error);
      out.converged = out.converged && r.converged && (!opt.compute_stiffness || r.stiffness_converged);
      out.force[k] = r.force;
      force_sum += r.force;
      if (opt.compute_stiffness) {
        out.stiffness[k] = r.stiffness;
        stiffness_sum += r.stiffness;
        frozen_sum += r.frozen_stiffness;
      }
    }
    out.mean_force = force_sum / static_cast<double>(count);
    out.k0 = opt.compute_stiffness ? stiffness_sum / static_cast<double>(count)
                                   : std::numeric_limits<double>::quiet_NaN();
    out.k0_frozen = opt.compute_stiffness ? frozen_sum / static_cast<double>(count)
                                          : std::numeric_limits<double>::quiet_NaN();
    return out;
  }

 private:
  // Undeformed gap s_i (BF-1) of strip cell (ix, iy) at position k.
  double strip_gap(std::size_t ix, std::size_t iy, std::size_t k) const {
    const double rx = strip_.x(ix) - positions_[k], ry = strip_.y(iy) - popt_.centre_y;
    return ball_height(rx * rx + ry * ry, radius_, shape_) - (heights_.empty() ? 0.0 : heights_[iy * strip_.nx + ix]);
  }

  // BF-5 at position k: limit_[k] = min s_i over the strip's edge cells and the cells outside the
  // window (an approach d ≤ limit_[k] leaves them without rigid interference).
  void approach_limit(std::size_t k) {
    const std::size_t nxw = solver_.grid().nx, nyw = solver_.grid().ny, ny = strip_.ny, nxs = strip_.nx;
    const std::size_t j = static_cast<std::size_t>(start_[k]), i0 = row0_;
    double limit = std::numeric_limits<double>::infinity();
    const char* where = "nothing";
    auto consider = [&](double gap, const char* place) {
      if (gap < limit) {
        limit = gap;
        where = place;
      }
    };
    const char* outside = "strip cells outside the solver window (enlarge it)";
    // Strip edges inside the window.
    for (std::size_t ix = j; ix < j + nxw; ++ix) {
      if (i0 == 0) consider(strip_gap(ix, 0, k), "the strip's edge (first row)");
      if (i0 + nyw == ny) consider(strip_gap(ix, ny - 1, k), "the strip's edge (last row)");
    }
    for (std::size_t iy = i0; iy < i0 + nyw; ++iy) {
      if (j == 0) consider(strip_gap(0, iy, k), "the strip's edge (first column)");
      if (j + nxw == nxs) consider(strip_gap(nxs - 1, iy, k), "the strip's edge (last column)");
    }
    // Rows outside the window (window columns only; the columns loop below covers the rest),
    // nearest first on each side, screened like the columns.
    auto row = [&](std::size_t iy) {
      const double ry = strip_.y(iy) - popt_.centre_y;
      const double z = ball_height(ry * ry, radius_, shape_);
      if (z - row_max_[iy] >= limit) return z - height_max_ >= limit;
      for (std::size_t ix = j; ix < j + nxw; ++ix)
        consider(strip_gap(ix, iy, k), iy == 0 || iy + 1 == ny ? "the strip's edge (first/last row)" : outside);
      return false;
    };
    for (std::size_t iy = i0; iy-- > 0;)
      if (row(iy) && strip_.y(iy) <= popt_.centre_y) break;
    for (std::size_t iy = i0 + nyw; iy < ny; ++iy)
      if (row(iy) && strip_.y(iy) >= popt_.centre_y) break;
    // Columns outside the window, nearest first on each side. A column is skipped when its bound
    // z_ball(|x − x_k|) − max_iy h cannot beat the limit; the side ends once the bound with the
    // strip's highest point cannot (z_ball grows with the distance).
    auto column = [&](std::size_t ix) {
      const double rx = strip_.x(ix) - positions_[k];
      const double z = ball_height(rx * rx, radius_, shape_);
      if (z - column_max_[ix] >= limit) return z - height_max_ >= limit;
      for (std::size_t iy = 0; iy < ny; ++iy)
        consider(strip_gap(ix, iy, k), ix == 0 || ix + 1 == nxs ? "the strip's edge (first/last column)" : outside);
      return false;
    };
    for (std::size_t ix = j; ix-- > 0;)
      if (column(ix) && strip_.x(ix) <= positions_[k]) break;
    for (std::size_t ix = j + nxw; ix < nxs; ++ix)
      if (column(ix) && strip_.x(ix) >= positions_[k]) break;
    limit_[k] = limit;
    limit_where_[k] = where;
  }

  ContactSolver& solver_;
  const Grid& strip_;
  const std::vector<double>& heights_;
  double radius_;
  BallShape shape_;
  const std::vector<double>& positions_;
  BlockedForceOptions popt_;
  std::vector<Index> start_, shift_;
  std::size_t row0_ = 0;  // first strip row of the window
  std::vector<double> column_max_, row_max_, window_heights_, limit_;
  std::vector<const char*> limit_where_;
  double height_max_ = 0.0;
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
                        bool warm, std::size_t store_count, double d_start, double step, BlockedForcePath& total,
                        const std::function<void(std::size_t, double)>& on_path) {
  // BF-5 caps the approach: the search stays at or below d_cap.
  std::size_t limiting = 0;
  const double d_cap = runner.max_approach(&limiting);
  double d = std::min(d_start, d_cap);
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  PathFields previous, current;
  for (int paths = 0;;) {
    BlockedForcePath path =
        runner.run(d, opt, paths > 0 && warm ? &previous : nullptr, warm ? &current : nullptr, store_count);
    ++paths;
    std::swap(previous, current);
    accumulate(total, path);
    const bool on_load = std::fabs(path.mean_force - load) <= tolerance * load;
    if (on_path) on_path(path.position.size(), std::fabs(path.mean_force - load) / load);
    if (path.mean_force < load) lo = d;
    else hi = d;
    const bool exhausted = std::isfinite(lo) && std::isfinite(hi) &&
                           hi - lo <= 1e-15 * std::max(std::fabs(hi), std::fabs(lo));
    if (!path.converged || on_load || paths >= max_paths || exhausted) {
      path.converged = path.converged && on_load;
      return path;
    }
    // Newton on F̄ with its exact slope K̄_f (BF-3).
    double next = path.k0_frozen > 0.0 ? d + (load - path.mean_force) / path.k0_frozen
                                       : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) {
      if (std::isfinite(lo) && std::isfinite(hi)) {
        next = 0.5 * (lo + hi);
      } else {
        next = path.mean_force < load ? d + step : d - step;
        step *= 2.0;
      }
    }
    if (next > d_cap) {
      if (d >= d_cap) {
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

}  // namespace

BlockedForcePath blocked_force_at_load(ContactSolver& solver, const Grid& strip,
                                       const std::vector<double>& strip_heights, double radius, BallShape shape,
                                       const std::vector<double>& positions, double load, const SolverOptions& options,
                                       const BlockedForceOptions& path_options) {
  if (!(load > 0.0) || !std::isfinite(load)) fail("load must be finite, > 0");
  if (!(path_options.load_tolerance > 0.0)) fail("load_tolerance must be > 0");
  PathRunner runner(solver, strip, strip_heights, radius, shape, positions, path_options);
  SolverOptions opt = options;
  opt.compute_stiffness = true;
  // BF-4: smooth Hertz approach for W; also the first bracket-growth step.
  const double d_hertz = std::pow(3.0 * load / (4.0 * solver.half_space().e_star() * std::sqrt(radius)), 2.0 / 3.0);
  // Fields kept between paths: all positions if they fit in max_stored_bytes, else the first.
  const bool warm = path_options.warm_start != PathWarmStart::Cold;
  const std::size_t field_bytes = 2 * sizeof(double) * solver.grid().size();
  const auto store_count = [&](std::size_t count) {
    return warm ? std::max<std::size_t>(1, std::min(count, path_options.max_stored_bytes / field_bytes)) : 0;
  };
  BlockedForcePath total;
  double d_start = d_hertz;
  // BF-4': pre-search on every S-th position to 1e-6, then the full path from there.
  const std::size_t m = path_options.presearch_positions;
  if (m > 0 && positions.size() >= 4 * m) {
    const std::size_t stride = positions.size() / m;
    std::vector<double> subset;
    for (std::size_t k = 0; k < positions.size(); k += stride) subset.push_back(positions[k]);
    PathRunner sub_runner(solver, strip, strip_heights, radius, shape, subset, path_options);
    const BlockedForcePath sub = search(sub_runner, opt, load, std::max(1e-6, path_options.load_tolerance),
                                        path_options.max_paths, warm, store_count(subset.size()), d_hertz, d_hertz,
                                        total, path_options.on_path);
    total.presearch_paths = total.paths;
    total.paths = 0;
    if (sub.converged) d_start = sub.approach;
  }
  BlockedForcePath path = search(runner, opt, load, path_options.load_tolerance, path_options.max_paths, warm,
                                 store_count(positions.size()), d_start, d_hertz, total, path_options.on_path);
  path.paths = total.paths;
  path.presearch_paths = total.presearch_paths;
  path.solves = total.solves;
  path.iterations = total.iterations;
  path.stiffness_iterations = total.stiffness_iterations;
  return path;
}

}  // namespace rollspec::contact
