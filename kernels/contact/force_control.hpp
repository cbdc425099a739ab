#pragma once
// Approach for a given total force, with any hardness (e.g. the ball's own weight, kernels/README.md (contact)).
#include <limits>
#include <vector>

#include "kernels/contact/contact_solver.hpp"

namespace rollspec::contact {

struct ForceControlOptions {
  double force_tolerance = 1e-10;  // stop when |P − F| ≤ force_tolerance · F
  int max_solves = 100;            // contact solves allowed (bracketing + Newton/bisection)
  // Warm start (e.g. the previous position of a path, equivalent_roughness.hpp): the first solve at
  // this approach from `pressure` as given, Newton from there with the bracket [first contact, +inf)
  // grown by steps; NaN: the cold bracket from first contact described below.
  double start_approach = std::numeric_limits<double>::quiet_NaN();
};

// Finds w with P(w) = force (N) on the open half-space by safeguarded Newton on the approach,
// using the frozen-set stiffness k = dP/dw (README Eq. 11) as the exact local derivative and
// bisection on a bracket [w_lo, w_hi] with P(w_lo) < F ≤ P(w_hi) (P(w) is non-decreasing; the
// bracket starts at first contact w = min s and grows geometrically). Every solve is
// warm-started from the previous field. Returns the last solve; `converged` is true only if that
// solve converged and |P − F| ≤ force_tolerance · F. Force 0 returns the solve at first contact.
// `options.compute_stiffness` is forced on.
ContactResult solve_force(ContactSolver& solver, const std::vector<double>& gap, double force,
                          std::vector<double>& pressure, const SolverOptions& options = {},
                          const ForceControlOptions& control = {});

}  // namespace rollspec::contact
