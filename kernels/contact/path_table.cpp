#include "kernels/contact/path_table.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include "kernels/contact/blocked_force.hpp"

namespace rollspec::contact {

namespace {

// z_ball(r) of README Eq. 5 (as ball_gap and blocked_force).
double ball_height(double r2, double radius, BallShape shape) {
  if (shape == BallShape::Paraboloid) return r2 / (2.0 * radius);
  return r2 < radius * radius ? r2 / (radius + std::sqrt(radius * radius - r2)) : radius;
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
  const double d_hertz = std::pow(3.0 * load / (4.0 * e_star * std::sqrt(radius)), 2.0 / 3.0);  // BF-4
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
  BlockedForceOptions bo;
  bo.centre_y = path_options.centre_y;
  // One approach per thread (each its own solver; the product inside runs on that thread alone).
  // The rows' numbers do not depend on which thread ran them. `strict`: a refused row (BF-5) is an
  // error; otherwise it and the rows above it are dropped (the extension of B43a stops there).
  const auto run_rows = [&](const std::vector<double>& d, bool strict) {
    std::vector<BlockedForcePath> rows(d.size());
    std::vector<unsigned char> refused(d.size(), 0);
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t j = static_cast<std::ptrdiff_t>(d.size()) - 1; j >= 0; --j) {
      const auto u = static_cast<std::size_t>(j);
      try {
        ContactSolver solver(window, e_star);
        rows[u] = blocked_force_path(solver, strip, heights, radius, shape, positions, d[u], opt, bo);
        if (path_options.on_row) {
#pragma omp critical(path_table_progress)
          path_options.on_row(d[u], rows[u].solves, rows[u].iterations);
        }
      } catch (const std::invalid_argument&) {
        if (strict) {
#pragma omp critical(path_table_error)
          if (!error) error = std::current_exception();
        }
        refused[u] = 1;
      } catch (...) {
#pragma omp critical(path_table_error)
        if (!error) error = std::current_exception();
      }
    }
    if (error) std::rethrow_exception(error);
    const auto first_refused = static_cast<std::size_t>(std::find(refused.begin(), refused.end(), 1) - refused.begin());
    rows.resize(first_refused);
    return rows;
  };
  t.converged = true;
  // Appends rows (B44: P non-decreasing in δ by a running maximum that acts at the solver's
  // tolerance only; 0 at or below first contact) and sets top_force = min_k P(δ_last, ξ_k) / W.
  const auto append = [&](const std::vector<BlockedForcePath>& rows) {
    for (const BlockedForcePath& r : rows) {
      const std::size_t j = t.force.size() / nk;
      t.solves += r.solves;
      t.iterations += r.iterations;
      t.max_error = std::max(t.max_error, r.max_error);
      t.converged = t.converged && r.converged;
      for (std::size_t k = 0; k < nk; ++k) {
        double p = r.approach > t.first_contact[k] ? std::max(r.force[k], 0.0) : 0.0;
        if (j > 0) p = std::max(p, t.force[(j - 1) * nk + k]);
        t.force.push_back(p);
      }
    }
    t.top_force = *std::min_element(t.force.end() - static_cast<std::ptrdiff_t>(nk), t.force.end()) / load;
  };
  t.force.clear();
  append(run_rows(t.approach, true));
  // B43a: a rough strip carries less than the smooth 3^{3/2} W at max δ_c + 3 δ_H; extend upwards
  // two rows at a time (a fixed batch, so the rows do not depend on the thread count).
  const double spacing = t.approach[1] - t.approach[0];
  const std::size_t batch = 2;
  while (t.top_force < path_options.top_force && t.approach.size() < path_options.max_approaches) {
    std::vector<double> more;
    for (std::size_t i = 0; i < batch && t.approach.size() + more.size() < path_options.max_approaches; ++i)
      more.push_back(t.approach.back() + spacing * static_cast<double>(i + 1));
    const std::vector<BlockedForcePath> rows = run_rows(more, false);
    for (const BlockedForcePath& r : rows) t.approach.push_back(r.approach);
    append(rows);
    if (rows.size() < more.size()) break;  // the window holds no more (BF-5)
  }
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
