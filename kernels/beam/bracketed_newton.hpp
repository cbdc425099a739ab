#pragma once
// The static approach of a monotone contact law: the root of p(x) = load inside a bracket [lo, hi]
// (p(lo) <= load <= p(hi)), by Newton steps on p's slope k, bisection where a step leaves the bracket or
// the slope is not positive. Converged when a step is below 1e-15 of step_scale(x, hi) or the bracket
// below 1e-15 of |hi|. The tabulated law (contact_law.cpp) and the path table (B46) share it.
#include <cmath>

namespace rollspec::beam {

// evaluate(x, p, k) sets p(x) and its slope k.
template <class Evaluate, class StepScale>
double bracketed_newton(double lo, double hi, double load, Evaluate&& evaluate, StepScale&& step_scale) {
  double x = 0.5 * (lo + hi), p = 0.0, k = 0.0;
  for (int it = 0; it < 200; ++it) {
    evaluate(x, p, k);
    const double r = p - load;
    if (r > 0.0)
      hi = x;
    else
      lo = x;
    double xn = k > 0.0 ? x - r / k : 0.5 * (lo + hi);
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
    if (std::fabs(xn - x) <= 1e-15 * step_scale(x, hi) || hi - lo <= 1e-15 * std::fabs(hi)) return xn;
    x = xn;
  }
  return x;
}

}  // namespace rollspec::beam
