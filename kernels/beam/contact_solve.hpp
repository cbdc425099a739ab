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

// The safeguarded iteration alone (every law; the linearised one off its contact branch).
ContactSolution solve_contact_force_iterative(const ContactModel& model, double delta_free, double rate_free,
                                              double compliance, double rate_compliance, double f0, double guess,
                                              double force_scale, double tolerance);

// Inline, so that the integrators' most common case, the linearised law in contact, costs no call.
inline ContactSolution solve_contact_force(const ContactModel& model, double delta_free, double rate_free,
                                           double compliance, double rate_compliance, double f0, double guess,
                                           double force_scale, double tolerance = 1e-13) {
  if (model.linearised()) {
    // (B21a) The linearised law is affine while the spring carries and the total pushes, so its root
    // is closed-form: F = (f0 + k0 (delta_free + d0) + c rate_free) / (1 + k0 C + c D). Accepted when
    // that branch holds at F (or tension is allowed); otherwise the safeguarded iteration finds the
    // root on the loss-of-contact branches.
    const ContactLaw& l = model.law();
    const double fl = (f0 + l.k0 * (delta_free + l.d0) + l.damping * rate_free) /
                      (1.0 + l.k0 * compliance + l.damping * rate_compliance);
    const double d = delta_free - compliance * fl;
    if (l.allow_tension || (fl > 0.0 && model.in_contact(d, f0)))
      return {fl, d, rate_free - rate_compliance * fl, model.in_contact(d, f0), 0};
  }
  return solve_contact_force_iterative(model, delta_free, rate_free, compliance, rate_compliance, f0, guess,
                                       force_scale, tolerance);
}

}  // namespace rollspec::beam
