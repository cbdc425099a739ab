#pragma once
// A uniformly sampled signal (roughness h(x) in space, blocked force F0(t) in time) with C^1
// cubic Hermite interpolation of value and derivative, README Eq. (B13): Catmull–Rom slopes
// (central differences, one-sided at the ends). Second-order accurate in the sample step, and
// smooth enough that the time integrators keep their design order between samples.
#include <cstddef>
#include <vector>

namespace rollspec::beam {

struct UniformSamples {
  double origin = 0.0;          // position (m) or time (s) of values[0]
  double step = 1.0;            // sample spacing, > 0
  std::vector<double> values;   // at origin + i * step

  bool empty() const { return values.empty(); }
  double end() const { return origin + step * static_cast<double>(values.size() - 1); }

  // Value and derivative at x; throws std::out_of_range outside [origin, end()] (a tolerance of
  // 1e-9 steps is allowed for rounding).
  void evaluate(double x, double& value, double& derivative) const;
  double value(double x) const;
};

}  // namespace rollspec::beam
