#include "kernels/contact/force_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rollspec::contact {

ContactResult solve_force(ContactSolver& solver, const std::vector<double>& gap, double force,
                          std::vector<double>& pressure, const SolverOptions& options,
                          const ForceControlOptions& control) {
  if (!(force >= 0.0) || !std::isfinite(force)) throw std::invalid_argument("solve_force: force must be finite, >= 0");
  if (solver.half_space().boundary() != Boundary::Open)
    throw std::invalid_argument("solve_force: open boundary only (periodic: use solve_load)");
  if (gap.size() != solver.grid().size()) throw std::invalid_argument("solve_force: gap size != grid size");
  SolverOptions opt = options;
  opt.compute_stiffness = true;
  const auto [lo_it, hi_it] = std::minmax_element(gap.begin(), gap.end());
  double w_lo = *lo_it;  // first contact: P(w_lo) = 0
  const double target_tol = control.force_tolerance * force;
  auto done = [&](const ContactResult& x) { return x.converged && std::fabs(x.force - force) <= target_tol; };
  if (std::isfinite(control.start_approach) && force > 0.0) {
    // Warm start: Newton from the given approach; P(w_lo) = 0 < F bounds it below, the upper end is
    // found by Newton or by steps growing 4× while P < F.
    double w = control.start_approach, w_hi = std::numeric_limits<double>::infinity();
    double step = std::max(1e-3 * (*hi_it - *lo_it), 1e-12 * std::max(1.0, std::fabs(w_lo)));
    ContactResult r = solver.solve(gap, w, pressure, opt);
    for (int solves = 1; r.converged && !done(r) && solves < control.max_solves; ++solves) {
      if (r.force >= force)
        w_hi = std::min(w_hi, w);
      else
        w_lo = std::max(w_lo, w);
      if (std::isfinite(w_hi) && w_hi - w_lo <= 1e-15 * std::max(std::fabs(w_hi), std::fabs(w_lo))) break;
      double w_next = r.frozen_stiffness > 0.0 ? w + (force - r.force) / r.frozen_stiffness
                                               : std::numeric_limits<double>::quiet_NaN();
      if (!(w_next > w_lo && w_next < w_hi)) {
        if (std::isfinite(w_hi)) {
          w_next = 0.5 * (w_lo + w_hi);
        } else {
          w_next = std::max(w, w_lo) + step;
          step *= 4.0;
        }
      }
      w = w_next;
      r = solver.solve(gap, w, pressure, opt);
    }
    r.converged = r.converged && done(r);
    return r;
  }
  ContactResult r = solver.solve(gap, w_lo, pressure, opt);
  if (force == 0.0) return r;

  // Bracket: grow the step from first contact until P ≥ F.
  double step = std::max(1e-3 * (*hi_it - *lo_it), 1e-12 * std::max(1.0, std::fabs(w_lo)));
  double w_hi = w_lo + step;
  int solves = 1;
  for (;;) {
    r = solver.solve(gap, w_hi, pressure, opt);
    ++solves;
    if (!r.converged || done(r)) {
      r.converged = r.converged && done(r);
      return r;
    }
    if (r.force >= force) break;
    if (solves >= control.max_solves) {
      r.converged = false;
      return r;
    }
    w_lo = w_hi;
    step *= 4.0;
    w_hi = w_lo + step;
  }
  // Safeguarded Newton inside [w_lo, w_hi]: the current iterate is w_hi with P ≥ F.
  double w = w_hi;
  while (solves < control.max_solves) {
    if (r.force >= force)
      w_hi = w;
    else
      w_lo = w;
    // Newton on the discrete P(w): its exact slope is the frozen-set k (README Eq. 11).
    double w_next = r.frozen_stiffness > 0.0 ? w + (force - r.force) / r.frozen_stiffness : 0.5 * (w_lo + w_hi);
    if (!(w_next > w_lo && w_next < w_hi)) w_next = 0.5 * (w_lo + w_hi);
    w = w_next;
    r = solver.solve(gap, w, pressure, opt);
    ++solves;
    if (!r.converged || done(r)) break;
    if (w_hi - w_lo <= 1e-15 * std::max(std::fabs(w_hi), std::fabs(w_lo))) break;  // bracket exhausted
  }
  r.converged = r.converged && done(r);
  return r;
}

}  // namespace rollspec::contact
