#include "kernels/contact/equivalent_roughness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/contact/chunk_loop.hpp"
#include "kernels/contact/force_control.hpp"
#include "kernels/contact/path_window.hpp"

namespace rollspec::contact {

namespace {

void check_load(double load) {
  if (!(load > 0.0) || !std::isfinite(load))
    throw std::invalid_argument("equivalent_roughness: load must be finite, > 0");
}

void record(EquivalentRoughness& out, std::size_t k, const ContactResult& r) {
  out.approach[k] = r.approach;
  out.contact_area[k] = r.contact_area;
  out.plastic_cells[k] = static_cast<double>(r.plastic_cells);
  out.stiffness[k] = r.stiffness;
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
  out.stiffness.assign(positions.size(), 0.0);
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
                                         const SolverOptions& options, const EquivalentRoughnessOptions& path_options) {
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
  // ER-1 in load control (README Eq. 17): one solve per position, the approach its multiplier.
  // A solve that does not converge is redone by the Newton of solve_force from the same start.
  auto solve = [&](ContactSolver& s, const std::vector<double>& gap, std::vector<double>& field, double hint,
                   const SolverOptions& o) {
    std::vector<double> start = field;
    ContactResult r = s.solve_at_force(gap, load, field, o, hint);
    r.converged = r.converged && std::fabs(r.force - load) <= path_options.load_tolerance * load;
    if (!r.converged) {
      ForceControlOptions c = control;
      c.start_approach = hint;
      field = start;
      const int first = r.iterations;
      r = solve_force(s, gap, load, field, o, c);
      r.iterations += first;
    }
    return r;
  };
  // ER-7: k at the found approach by a displacement solve from a copy of the field (the field itself
  // stays the next position's warm start); that solve meets Eq. 9 at once (the same solution).
  auto stiffness_at = [&](ContactSolver& s, const std::vector<double>& gap, double approach,
                          const std::vector<double>& field) {
    std::vector<double> copy = field;
    SolverOptions o = options;
    o.compute_stiffness = true;
    return s.solve(gap, approach, copy, o).stiffness;
  };
  const std::size_t every = path_options.stiffness_every;
  const ContactResult smooth = solve(solver, flat.gap(0), p, std::numeric_limits<double>::quiet_NaN(), options);
  out.smooth_approach = smooth.approach;
  out.smooth_contact_area = smooth.contact_area;
  out.smooth_stiffness =
      every > 0 ? stiffness_at(solver, flat.gap(0), smooth.approach, p) : std::numeric_limits<double>::quiet_NaN();
  out.iterations += smooth.iterations;
  out.converged = smooth.converged;
  if (smooth.approach > flat.limit(0)) flat.reject(0, smooth.approach, "flat strip: ");
  // One chunk [k0, k1): from the flat field and δ_smooth, then BF-6 and the previous δ_eq.
  const std::vector<double> p_smooth = p;
  std::vector<ContactResult> results(positions.size());
  // ER-8: the loose solves' options, and each checked position's full-tolerance approach (NaN elsewhere).
  const bool loose = path_options.answer_tolerance > 0.0;
  SolverOptions loose_options = options;
  if (loose) loose_options.tolerance = std::max(options.tolerance, path_options.answer_tolerance);
  const std::size_t stride = loose ? path_options.check_stride : 0;
  std::vector<double> checked(positions.size(), std::numeric_limits<double>::quiet_NaN());
  auto run_chunk = [&](ContactSolver& chunk_solver, std::size_t k0, std::size_t k1) {
    std::vector<double> field = p_smooth, check_field;
    for (std::size_t k = k0; k < k1; ++k) {
      double hint = out.smooth_approach;
      if (path_options.warm_start) {
        // BF-6: previous field shifted with the ball; the previous δ_eq lists the cells (Eq. 17).
        if (k > k0) window.shift_field(field, window.ball_shift(k));
        if (k > k0) hint = results[k - 1].approach;
      } else {
        field.assign(chunk_solver.grid().size(), 0.0);
      }
      results[k] = solve(chunk_solver, window.gap(k), field, hint, loose_options);
      if (stride > 0 && k % stride == stride / 2) {  // ER-8: the same position to the full tolerance
        check_field = field;
        const ContactResult full = solve(chunk_solver, window.gap(k), check_field, results[k].approach, options);
        checked[k] = full.approach;
        results[k].iterations += full.iterations;
      }
      results[k].stiffness = every > 0 && k % every == 0
                                 ? stiffness_at(chunk_solver, window.gap(k), results[k].approach, field)
                                 : std::numeric_limits<double>::quiet_NaN();
    }
  };
  const std::size_t n = positions.size();
  const std::size_t chunk = path_options.chunk_positions == 0 ? n : path_options.chunk_positions;
  const std::size_t chunks = (n + chunk - 1) / chunk;
  if (chunks <= 1) {
    run_chunk(solver, 0, n);
  } else {
    // Chunks in parallel, a fresh solver per chunk (no state carried from whichever chunk a thread
    // ran before; the solver's own loops run on that thread: same bits, README test_threads).
    // Exceptions are carried out of the parallel region (chunk_loop.hpp).
    detail::for_each_chunk(chunks, 0, [&](std::size_t c, int) {
      ContactSolver own(solver.grid(), solver.half_space().e_star());
      const std::size_t k0 = c * chunk;
      run_chunk(own, k0, std::min(n, k0 + chunk));
    });
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (results[k].approach > window.limit(k)) window.reject(k, results[k].approach);  // BF-5 at δ_eq
    record(out, k, results[k]);
  }
  finish(out);
  for (std::size_t k = 0; k < n; ++k)
    if (std::isfinite(checked[k])) {  // ER-8: h_full − h_loose = δ_loose − δ_full
      out.check_index.push_back(k);
      out.check_residual.push_back(results[k].approach - checked[k]);
    }
  return out;
}

EquivalentRoughness equivalent_roughness_reference(const Grid& strip, const std::vector<double>& strip_heights,
                                                   double radius, BallShape shape, const std::vector<double>& positions,
                                                   double load, double e_star, const SolverOptions& options,
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
  const ContactResult smooth = solve_force(
      solver, ball_gap(strip, radius, {}, shape, positions.at(0), path_options.centre_y), load, p, options, control);
  out.smooth_approach = smooth.approach;
  out.smooth_contact_area = smooth.contact_area;
  out.smooth_stiffness = smooth.stiffness;
  out.converged = smooth.converged;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    p.clear();
    const ContactResult r =
        solve_force(solver, ball_gap(strip, radius, strip_heights, shape, positions[k], path_options.centre_y), load, p,
                    options, control);
    record(out, k, r);
  }
  finish(out);
  return out;
}

}  // namespace rollspec::contact
