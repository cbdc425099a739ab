#pragma once
// A uniformly sampled signal (roughness h(x) in space, blocked force F0(t) in time) with C^1
// cubic Hermite interpolation of value and derivative, README Eq. (B13): Catmull–Rom slopes
// (central differences, one-sided at the ends). Second-order accurate in the sample step, and
// smooth enough that the time integrators keep their design order between samples.
// Inline: the exact-step integrator reads F0 or h once per step.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace rollspec::beam {

struct UniformSamples {
  double origin = 0.0;         // position (m) or time (s) of values[0]
  double step = 1.0;           // sample spacing, > 0
  std::vector<double> values;  // at origin + i * step

  bool empty() const { return values.empty(); }
  double end() const { return origin + step * static_cast<double>(values.size() - 1); }

  // Value and derivative at x; throws std::out_of_range outside [origin, end()] (a tolerance of
  // 1e-9 steps is allowed for rounding).
  void evaluate(double x, double& value, double& derivative) const {
    const Cell c = locate(x);
    const double t = c.t, t2 = t * t, t3 = t2 * t;
    value = (2 * t3 - 3 * t2 + 1) * c.y0 + (t3 - 2 * t2 + t) * c.m0 + (-2 * t3 + 3 * t2) * c.y1 + (t3 - t2) * c.m1;
    derivative =
        ((6 * t2 - 6 * t) * c.y0 + (3 * t2 - 4 * t + 1) * c.m0 + (-6 * t2 + 6 * t) * c.y1 + (3 * t2 - 2 * t) * c.m1) /
        step;
  }
  // The value alone: evaluate()'s operations without the derivative's.
  double value(double x) const {
    const Cell c = locate(x);
    const double t = c.t, t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * c.y0 + (t3 - 2 * t2 + t) * c.m0 + (-2 * t3 + 3 * t2) * c.y1 + (t3 - t2) * c.m1;
  }

 private:
  // Interval i and fraction t of x, the samples at its ends and their Catmull–Rom slopes in units
  // of "per sample" (B13).
  struct Cell {
    double t, y0, y1, m0, m1;
  };
  Cell locate(double x) const {
    const std::size_t n = values.size();
    if (n < 2 || !(step > 0.0)) throw_bad_samples();
    double u = (x - origin) / step;
    const double last = static_cast<double>(n - 1);
    if (!(u >= -1e-9 && u <= last + 1e-9)) throw_out_of_range();
    u = std::min(std::max(u, 0.0), last);
    std::size_t i = static_cast<std::size_t>(u);
    if (i >= n - 1) i = n - 2;
    Cell c;
    c.t = u - static_cast<double>(i);
    c.y0 = values[i];
    c.y1 = values[i + 1];
    c.m0 = i > 0 ? 0.5 * (c.y1 - values[i - 1]) : c.y1 - c.y0;
    c.m1 = i + 2 < n ? 0.5 * (values[i + 2] - c.y0) : c.y1 - c.y0;
    return c;
  }
  [[noreturn]] static void throw_bad_samples();
  [[noreturn]] static void throw_out_of_range();
};

}  // namespace rollspec::beam
