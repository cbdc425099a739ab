#pragma once
// Implicit scalar contact solve, README Eq. (B21). At a step end (or at an instant, for the
// reference integrator) the compression and its rate are affine in the unknown contact force F:
//   delta(F) = delta_free - C F,   delta_dot(F) = rate_free - D F,   C, D >= 0,
// so F solves r(F) = F - law(delta(F), delta_dot(F)) = 0. r(0) <= 0 and r' = 1 + C k + D c >= 1 on
// every branch, so the root is unique; Newton's iteration is safeguarded by the bracket [lo, hi]
// (bisection when a Newton step leaves it), which also handles the kinks at loss of contact.
// The linearised law's contact branch is solved in closed form (B21a; `iterations` 0).
#include "kernels/beam/contact_law.hpp"

namespace rollspec::beam {

struct ContactSolution {
  double force;
  double delta;
  double rate;
  bool contact;
  int iterations;
};

ContactSolution solve_contact_force(const ContactModel& model, double delta_free, double rate_free, double compliance,
                                    double rate_compliance, double f0, double guess, double force_scale,
                                    double tolerance = 1e-13);

}  // namespace rollspec::beam
