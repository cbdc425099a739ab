#include "kernels/contact/equivalent_roughness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/contact/force_control.hpp"
#include "kernels/contact/path_window.hpp"

namespace rollspec::contact {

namespace {

void check_load(double load) {
  if (!(load > 0.0) || !std::isfinite(load)) throw std::invalid_argument("equivalent_roughness: load must be finite, > 0");
}

void record(EquivalentRoughness& out, std::size_t k, const ContactResult& r) {
  out.approach[k] = r.approach;
  out.contact_area[k] = r.contact_area;
  out.plastic_cells[k] = static_cast<double>(r.plastic_cells);
  out.iterations += r.iterations;
  out.max_error = std::max(out.max_error, r.error);
  out.converged = out.converged && r.converged;
}

EquivalentRoughness empty_result(const std::vector<double>& positions) {
  EquivalentRoughness out;
  out.position = positions;
  out.approach.assign(positions.size(), 0.0);
  out.height.assign(positions.size(), 0.0);
  out.contact_area.assign(positions.size(), 0.0);
  out.plastic_cells.assign(positions.size(), 0.0);
  out.converged = true;
  return out;
}

void finish(EquivalentRoughness& out) {
  for (std::size_t k = 0; k < out.approach.size(); ++k) out.height[k] = out.smooth_approach - out.approach[k];  // ER-2
}

}  // namespace

EquivalentRoughness equivalent_roughness(ContactSolver& solver, const Grid& strip,
                                         const std::vector<double>& strip_heights, double radius, BallShape shape,
                                         const std::vector<double>& positions, double load,
                                         const SolverOptions& options,
                                         const EquivalentRoughnessOptions& path_options) {
  check_load(load);
  if (solver.half_space().boundary() != Boundary::Open)
    throw std::invalid_argument("equivalent_roughness: the solver must use the open boundary");
  PathWindow window(solver.grid(), strip, strip_heights, radius, shape, positions, path_options.centre_y,
                    "equivalent_roughness");
  // δ_smooth: the same window at position 0 on a flat strip (whole-cell moves of the ball leave the
  // discrete flat problem unchanged, so one solve serves every position).
  const std::vector<double> no_heights;
  PathWindow flat(solver.grid(), strip, no_heights, radius, shape, {positions[0]}, path_options.centre_y,
                  "equivalent_roughness");
  ForceControlOptions control;
  control.force_tolerance = path_options.load_tolerance;
  control.max_solves = path_options.max_solves;
  EquivalentRoughness out = empty_result(positions);
  std::vector<double> p;
  const ContactResult smooth = solve_force(solver, flat.gap(0), load, p, options, control);
  out.smooth_approach = smooth.approach;
  out.smooth_contact_area = smooth.contact_area;
  out.iterations += smooth.iterations;
  out.converged = smooth.converged;
  if (smooth.approach > flat.limit(0)) flat.reject(0, smooth.approach, "flat strip: ");
  for (std::size_t k = 0; k < positions.size(); ++k) {
    if (path_options.warm_start) {
      // BF-6: previous field shifted with the ball; Newton from the previous δ_eq (δ_smooth at k = 0).
      if (k > 0) window.shift_field(p, window.ball_shift(k));
      control.start_approach = k > 0 ? out.approach[k - 1] : out.smooth_approach;
    } else {
      p.assign(solver.grid().size(), 0.0);
    }
    const ContactResult r = solve_force(solver, window.gap(k), load, p, options, control);
    if (r.approach > window.limit(k)) window.reject(k, r.approach);  // BF-5 at δ_eq
    record(out, k, r);
  }
  finish(out);
  return out;
}

EquivalentRoughness equivalent_roughness_reference(const Grid& strip, const std::vector<double>& strip_heights,
                                                   double radius, BallShape shape,
                                                   const std::vector<double>& positions, double load, double e_star,
                                                   const SolverOptions& options,
                                                   const EquivalentRoughnessOptions& path_options) {
  check_load(load);
  check_grid(strip);
  if (!strip_heights.empty() && strip_heights.size() != strip.size())
    throw std::invalid_argument("equivalent_roughness: strip heights size != strip grid size");
  ContactSolver solver(strip, e_star);
  ForceControlOptions control;
  control.force_tolerance = path_options.load_tolerance;
  control.max_solves = path_options.max_solves;
  EquivalentRoughness out = empty_result(positions);
  std::vector<double> p;
  const ContactResult smooth =
      solve_force(solver, ball_gap(strip, radius, {}, shape, positions.at(0), path_options.centre_y), load, p,
                  options, control);
  out.smooth_approach = smooth.approach;
  out.smooth_contact_area = smooth.contact_area;
  out.converged = smooth.converged;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    p.clear();
    const ContactResult r = solve_force(
        solver, ball_gap(strip, radius, strip_heights, shape, positions[k], path_options.centre_y), load, p, options,
        control);
    record(out, k, r);
  }
  finish(out);
  return out;
}

}  // namespace rollspec::contact
