#include "kernels/contact/path_table.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include "kernels/contact/chunk_loop.hpp"
#include "kernels/contact/hertz.hpp"
#include "kernels/contact/path_window.hpp"

#include <omp.h>

#include <memory>

namespace rollspec::contact {

namespace {

// z_ball(r) of README Eq. 5 (as ball_gap and blocked_force).
double ball_height(double r2, double radius, BallShape shape) {
  if (shape == BallShape::Paraboloid) return r2 / (2.0 * radius);
  return r2 < radius * radius ? r2 / (radius + std::sqrt(radius * radius - r2)) : radius;
}

// The rows `d` (increasing) of the table over every position (PT-1): force at [r · N + k]. With an
// `origin` per position (B43b) row r stands at origin_k + d_r, and rows past `min_rows` are solved
// only while the row below carries less than `target` and the window holds them (BF-5); the rows a
// position does not solve hold NaN and `rows` counts those it did.
struct Rows {
  std::vector<double> approach, force;
  std::vector<std::size_t> rows;
  int solves = 0, iterations = 0;
  double max_error = 0.0;
  bool converged = true;
};

struct Ladder {
  const std::vector<double>* origin = nullptr;  // null: every row at d_r (B43)
  std::size_t min_rows = 0;
  double target = 0.0;
};

Rows path_rows(const PathWindow& win, const Grid& window, double e_star, const std::vector<double>& d,
               const SolverOptions& opt, const PathTableOptions& po, const Ladder& ladder = {}) {
  const std::size_t nk = win.size(), nj = d.size(), n = window.size();
  Rows out;
  out.approach = d;
  out.force.assign(nj * nk, std::numeric_limits<double>::quiet_NaN());
  out.rows.assign(nk, 0);
  if (nj == 0) return out;
  struct Solved {  // what the table keeps of a solve (a ContactResult per cell would be 5x larger)
    double force = 0.0, error = 0.0;
    int iterations = 0;
    bool converged = false;
  };
  std::vector<Solved> results(nj * nk);
  const std::size_t chunk = po.chunk_positions == 0 ? nk : std::min(nk, po.chunk_positions);
  const std::size_t chunks = (nk + chunk - 1) / chunk;
  const int threads = std::max(1, std::min<int>(omp_get_max_threads(), static_cast<int>(chunks)));
  // One solver per thread, made outside the parallel region; a solve depends on its inputs only.
  std::vector<std::unique_ptr<ContactSolver>> solvers;
  for (int i = 0; i < threads; ++i) solvers.push_back(std::make_unique<ContactSolver>(window, e_star));
  std::size_t done = 0;
  detail::for_each_chunk(chunks, threads, [&](std::size_t c, int thread) {
    ContactSolver& s = *solvers[static_cast<std::size_t>(thread)];
    const std::size_t k0 = c * chunk, k1 = std::min(nk, k0 + chunk);
    std::vector<std::vector<double>> fields(nj);  // each row's last field in this chunk
    std::vector<double> p;
    int solves = 0, iterations = 0;
    std::size_t most_rows = 0;
    for (std::size_t k = k0; k < k1; ++k) {
      const std::vector<double> gap = win.gap(k);
      const double origin = ladder.origin ? (*ladder.origin)[k] : 0.0;
      std::size_t j = 0;
      for (; j < nj; ++j) {
        const double dj = origin + d[j];
        if (ladder.origin && j >= ladder.min_rows &&
            (results[(j - 1) * nk + k].force >= ladder.target || dj > win.limit(k)))
          break;  // B43b: this position's ladder is done
        if (po.start == PathTableStart::Cold || (k == k0 && (j == 0 || po.start == PathTableStart::Position))) {
          p.assign(n, 0.0);
        } else if (po.start == PathTableStart::Approach && j > 0) {
          p = fields[j - 1];  // PT-1: the approach below, this position
          if (j > 1) {        // PT-1: extrapolated along the two approaches below
            const double f = (d[j] - d[j - 1]) / (d[j - 1] - d[j - 2]);
            for (std::size_t i = 0; i < n; ++i) p[i] += f * (fields[j - 1][i] - fields[j - 2][i]);
          }
        } else if (fields[j].empty()) {
          p.assign(n, 0.0);  // B43b: no earlier position in this chunk reached this row
        } else {
          p = fields[j];  // BF-6: this approach, the previous position, shifted with the ball
          win.shift_field(p, win.ball_shift(k));
        }
        const ContactResult r = s.solve(gap, dj, p, opt);
        results[j * nk + k] = Solved{r.force, r.error, r.iterations, r.converged};
        fields[j] = p;
        ++solves;
        iterations += r.iterations;
      }
      out.rows[k] = j;
      most_rows = std::max(most_rows, j);
    }
    if (po.on_chunk) {
#pragma omp critical(path_table_progress)
      {
        done += k1 - k0;
        po.on_chunk(most_rows, done, solves, iterations);
      }
    }
  });
  for (std::size_t k = 0; k < nk; ++k)
    for (std::size_t j = 0; j < out.rows[k]; ++j) {
      const Solved& r = results[j * nk + k];
      out.force[j * nk + k] = r.force;
      ++out.solves;
      out.iterations += r.iterations;
      out.max_error = std::max(out.max_error, r.error);
      out.converged = out.converged && r.converged;
    }
  return out;
}

}  // namespace

std::vector<double> first_contact_approach(const Grid& strip, const std::vector<double>& heights, double radius,
                                           BallShape shape, const std::vector<double>& positions, double centre_y,
                                           std::size_t half_columns) {
  check_grid(strip);
  if (!heights.empty() && heights.size() != strip.size())
    throw std::invalid_argument("first_contact_approach: heights size != strip grid size");
  std::vector<double> out(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) {
    std::size_t lo = 0, hi = strip.nx;
    if (half_columns > 0) {
      const double col = positions[k] / strip.dx + 0.5 * static_cast<double>(strip.nx - 1);
      const double a = std::max(0.0, std::floor(col) - static_cast<double>(half_columns));
      const double b =
          std::min(static_cast<double>(strip.nx), std::ceil(col) + static_cast<double>(half_columns) + 1.0);
      lo = static_cast<std::size_t>(a);
      hi = static_cast<std::size_t>(std::max(a, b));
    }
    double m = std::numeric_limits<double>::infinity();  // B42: min_i s_i
    for (std::size_t iy = 0; iy < strip.ny; ++iy) {
      const double ry = strip.y(iy) - centre_y;
      for (std::size_t ix = lo; ix < hi; ++ix) {
        const double rx = strip.x(ix) - positions[k];
        const double s =
            ball_height(rx * rx + ry * ry, radius, shape) - (heights.empty() ? 0.0 : heights[iy * strip.nx + ix]);
        m = std::min(m, s);
      }
    }
    out[k] = m;
  }
  return out;
}

std::vector<double> path_table_approaches(const std::vector<double>& first_contact, double load, double e_star,
                                          double radius, const PathTableOptions& o) {
  if (first_contact.empty()) throw std::invalid_argument("path_table: no positions");
  if (o.approaches < 2) throw std::invalid_argument("path_table: at least 2 approaches");
  if (!(load > 0.0) || !(e_star > 0.0) || !(radius > 0.0) || !(o.reach > 0.0))
    throw std::invalid_argument("path_table: load, E*, radius and reach must be > 0");
  const double d_hertz = hertz::approach_at_load(radius, e_star, load);  // BF-4
  if (o.ladder == PathLadder::FirstContact) {                            // B43b
    std::vector<double> s(std::max(o.approaches, o.max_approaches));
    for (std::size_t j = 0; j < s.size(); ++j)
      s[j] = o.reach * d_hertz * static_cast<double>(j + 1) / static_cast<double>(o.approaches);
    return s;
  }
  const auto mm = std::minmax_element(first_contact.begin(), first_contact.end());
  const double lo = *mm.first, hi = *mm.second + o.reach * d_hertz;  // B43
  std::vector<double> d(o.approaches);
  for (std::size_t j = 0; j < d.size(); ++j)
    d[j] = lo + (hi - lo) * static_cast<double>(j + 1) / static_cast<double>(o.approaches);
  return d;
}

PathTable build_path_table(const Grid& window, double e_star, const Grid& strip, const std::vector<double>& heights,
                           double radius, BallShape shape, const std::vector<double>& positions, double load,
                           const SolverOptions& options, const PathTableOptions& path_options) {
  PathTable t;
  t.position = positions;
  t.first_contact =
      first_contact_approach(strip, heights, radius, shape, positions, path_options.centre_y, window.nx / 2 + 1);
  t.approach = path_table_approaches(t.first_contact, load, e_star, radius, path_options);
  const std::size_t nk = positions.size();
  SolverOptions opt = options;
  opt.compute_stiffness = false;
  const PathWindow win(window, strip, heights, radius, shape, positions, path_options.centre_y, "blocked_force");
  // `strict`: a row beyond the window's limit (BF-5) is an error; otherwise it and the rows above it
  // are dropped (the extension of B43a stops there).
  const auto run_rows = [&](std::vector<double> d, bool strict) {
    std::size_t limiting = 0;
    const double cap = win.max_approach(&limiting);
    const auto first_refused =
        static_cast<std::size_t>(std::find_if(d.begin(), d.end(), [&](double a) { return a > cap; }) - d.begin());
    if (strict && first_refused < d.size()) win.reject(limiting, d[first_refused]);
    d.resize(first_refused);
    return path_rows(win, window, e_star, d, opt, path_options);
  };
  t.converged = true;
  // Appends rows (B44: P non-decreasing in δ by a running maximum that acts at the solver's
  // tolerance only; 0 at or below first contact) and sets top_force = min_k P(δ_last, ξ_k) / W.
  const auto append = [&](const Rows& rows) {
    t.solves += rows.solves;
    t.iterations += rows.iterations;
    t.max_error = std::max(t.max_error, rows.max_error);
    t.converged = t.converged && rows.converged;
    for (std::size_t r = 0; r < rows.approach.size(); ++r) {
      const std::size_t j = t.force.size() / nk;
      for (std::size_t k = 0; k < nk; ++k) {
        const double f = rows.force[r * nk + k];
        double p = rows.approach[r] > t.first_contact[k] ? std::max(f, 0.0) : 0.0;
        if (j > 0) p = std::max(p, t.force[(j - 1) * nk + k]);
        t.force.push_back(p);
      }
    }
    t.top_force = *std::min_element(t.force.end() - static_cast<std::ptrdiff_t>(nk), t.force.end()) / load;
  };
  t.force.clear();
  if (path_options.ladder == PathLadder::FirstContact) {  // B43b: each position's own ladder
    t.ladder = PathLadder::FirstContact;
    for (std::size_t k = 0; k < nk; ++k)  // the J rows every position solves must fit the window (BF-5)
      if (t.first_contact[k] + t.approach[path_options.approaches - 1] > win.limit(k))
        win.reject(k, t.first_contact[k] + t.approach[path_options.approaches - 1]);
    Rows rows = path_rows(win, window, e_star, t.approach, opt, path_options,
                          Ladder{&t.first_contact, path_options.approaches, path_options.top_force * load});
    const std::size_t most = *std::max_element(rows.rows.begin(), rows.rows.end());
    t.approach.resize(most);
    rows.force.resize(most * nk);
    t.solves = rows.solves;
    t.iterations = rows.iterations;
    t.max_error = rows.max_error;
    t.converged = rows.converged;
    t.rows = rows.rows;
    t.top_force = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < nk; ++k) {  // B44: non-decreasing by a running maximum (the solver's tolerance)
      for (std::size_t j = 0; j < t.rows[k]; ++j)
        rows.force[j * nk + k] = std::max(rows.force[j * nk + k], j > 0 ? rows.force[(j - 1) * nk + k] : 0.0);
      t.top_force = std::min(t.top_force, rows.force[(t.rows[k] - 1) * nk + k] / load);
    }
    t.force = std::move(rows.force);
    return t;
  }
  append(run_rows(t.approach, true));
  // B43a: a rough strip carries less than the smooth 3^{3/2} W at max δ_c + 3 δ_H; extend upwards
  // two rows at a time (a fixed batch, so the rows do not depend on the thread count).
  const double spacing = t.approach[1] - t.approach[0];
  const std::size_t batch = 2;
  while (t.top_force < path_options.top_force && t.approach.size() < path_options.max_approaches) {
    std::vector<double> more;
    for (std::size_t i = 0; i < batch && t.approach.size() + more.size() < path_options.max_approaches; ++i)
      more.push_back(t.approach.back() + spacing * static_cast<double>(i + 1));
    const Rows rows = run_rows(more, false);
    for (double a : rows.approach) t.approach.push_back(a);
    append(rows);
    if (rows.approach.size() < more.size()) break;  // the window holds no more (BF-5)
  }
  t.rows.assign(nk, t.approach.size());
  return t;
}

double path_force_direct(const Grid& strip, const std::vector<double>& heights, double e_star, double radius,
                         BallShape shape, double x, double centre_y, double approach, const SolverOptions& options) {
  SolverOptions opt = options;
  opt.compute_stiffness = false;
  ContactSolver solver(strip, e_star);
  const std::vector<double> gap = ball_gap(strip, radius, heights, shape, x, centre_y);
  std::vector<double> p;
  const ContactResult r = solver.solve(gap, approach, p, opt);
  if (!r.converged) throw std::runtime_error("path_force_direct: contact solve did not converge");
  return r.force;
}

}  // namespace rollspec::contact
