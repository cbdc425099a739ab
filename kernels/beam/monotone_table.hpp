#pragma once
// Monotone piecewise-cubic Hermite interpolation of a table y(x) (Fritsch & Butland 1984, the
// PCHIP of scipy / MATLAB), README Eq. (B14): slopes are weighted harmonic means of the adjacent
// secants (zero where the data turn), so a monotone table gives a monotone, C^1 interpolant with
// no overshoot, and its derivative is the tangent stiffness of a force table P(delta).
// Outside the table: linear extrapolation with the end slope.
#include <vector>

namespace rollspec::beam {

class MonotoneTable {
 public:
  MonotoneTable() = default;
  // x strictly increasing, at least 2 points.
  MonotoneTable(std::vector<double> x, std::vector<double> y);

  bool empty() const { return x_.empty(); }
  void evaluate(double x, double& y, double& dy) const;
  double operator()(double x) const;
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_, d_;
};

}  // namespace rollspec::beam
