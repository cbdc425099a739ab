#include "kernels/beam/contact_solve.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rollspec::beam {

ContactSolution solve_contact_force_iterative(const ContactModel& model, double delta_free, double rate_free,
                                              double compliance, double rate_compliance, double f0, double guess,
                                              double force_scale, double tolerance) {
  auto at = [&](double f) { return model.evaluate(delta_free - compliance * f, rate_free - rate_compliance * f, f0); };
  const bool tension = model.linearised() && model.law().allow_tension;
  ContactForce c0 = at(0.0);
  if (!tension && c0.force <= 0.0) return {0.0, delta_free, rate_free, c0.contact, 0};
  double lo = tension ? -std::numeric_limits<double>::infinity() : 0.0;
  double hi = std::numeric_limits<double>::infinity();
  double f = (guess > lo) ? guess : c0.force;
  const double scale = std::abs(force_scale) > 0.0 ? std::abs(force_scale) : 1.0;
  for (int it = 1; it <= 200; ++it) {
    const ContactForce c = at(f);
    const double r = f - c.force;
    if (r == 0.0) return {f, delta_free - compliance * f, rate_free - rate_compliance * f, c.contact, it};
    if (r < 0.0)
      lo = f;
    else
      hi = f;
    const double dr = 1.0 + compliance * c.d_delta + rate_compliance * c.d_rate;
    double fn = f - r / dr;
    if (!(fn > lo && fn < hi)) {
      if (std::isfinite(lo) && std::isfinite(hi))
        fn = 0.5 * (lo + hi);
      else if (std::isfinite(lo))
        fn = 2.0 * std::max(lo, scale);  // expand upward
      else
        fn = hi - 2.0 * std::max(std::abs(hi), scale);  // expand downward (tension only)
    }
    // Newton converges quadratically on each smooth branch: once a step is below sqrt(tol), the
    // next one would be below tol, so fn is accepted without another evaluation.
    const double size = std::abs(fn) + scale;
    const bool smooth_step = std::abs(fn - f) <= std::sqrt(tolerance) * 0.1 * size && fn > lo && fn < hi &&
                             model.in_contact(delta_free - compliance * fn, f0) == c.contact;
    if (smooth_step || std::abs(fn - f) <= tolerance * size ||
        (std::isfinite(lo) && std::isfinite(hi) && hi - lo <= tolerance * (std::abs(hi) + scale))) {
      const double d = delta_free - compliance * fn;
      return {fn, d, rate_free - rate_compliance * fn, model.in_contact(d, f0), it};
    }
    f = fn;
  }
  throw std::runtime_error("solve_contact_force: no convergence");
}

}  // namespace rollspec::beam
