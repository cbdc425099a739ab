// Piecewise-linear time series s(t) (load and imposed-displacement multipliers), held
// constant outside the table.
#pragma once

#include <vector>

namespace rollspec::rolling {

struct TimeSeries {
  std::vector<double> t{0.0};
  std::vector<double> v{1.0};

  double operator()(double time) const;

  static TimeSeries constant(double c = 1.0) { return TimeSeries{{0.0}, {c}}; }
  // 0 at t0, 1 at t1 and after.
  static TimeSeries ramp(double t0, double t1) { return TimeSeries{{t0, t1}, {0.0, 1.0}}; }
};

}  // namespace rollspec::rolling
