#include "kernels/beam/monotone_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollspec::beam {

namespace {
double sign(double v) { return (v > 0.0) - (v < 0.0); }
}  // namespace

MonotoneTable::MonotoneTable(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
  const std::size_t n = x_.size();
  if (n < 2 || y_.size() != n) throw std::invalid_argument("MonotoneTable: need >= 2 (x, y) pairs of equal length");
  for (std::size_t i = 1; i < n; ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("MonotoneTable: x must be strictly increasing");
  std::vector<double> h(n - 1), s(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x_[i + 1] - x_[i];
    s[i] = (y_[i + 1] - y_[i]) / h[i];
  }
  d_.assign(n, 0.0);
  if (n == 2) {
    d_[0] = d_[1] = s[0];
    return;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {  // (B14) weighted harmonic mean
    if (s[k - 1] * s[k] <= 0.0) continue;
    const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
    d_[k] = (w1 + w2) / (w1 / s[k - 1] + w2 / s[k]);
  }
  // Shape-preserving three-point end slopes.
  auto end_slope = [](double h0, double h1, double s0, double s1) {
    double d = ((2.0 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
    if (sign(d) != sign(s0))
      d = 0.0;
    else if (sign(s0) != sign(s1) && std::abs(d) > 3.0 * std::abs(s0))
      d = 3.0 * s0;
    return d;
  };
  d_[0] = end_slope(h[0], h[1], s[0], s[1]);
  d_[n - 1] = end_slope(h[n - 2], h[n - 3], s[n - 2], s[n - 3]);
}

void MonotoneTable::evaluate(double x, double& y, double& dy) const {
  const std::size_t n = x_.size();
  if (n == 0) throw std::logic_error("MonotoneTable: empty");
  if (x <= x_[0]) {
    dy = d_[0];
    y = y_[0] + d_[0] * (x - x_[0]);
    return;
  }
  if (x >= x_[n - 1]) {
    dy = d_[n - 1];
    y = y_[n - 1] + d_[n - 1] * (x - x_[n - 1]);
    return;
  }
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double h = x_[i + 1] - x_[i], t = (x - x_[i]) / h, t2 = t * t, t3 = t2 * t;
  y = (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * h * d_[i] + (-2 * t3 + 3 * t2) * y_[i + 1] +
      (t3 - t2) * h * d_[i + 1];
  dy = (6 * t2 - 6 * t) / h * (y_[i] - y_[i + 1]) + (3 * t2 - 4 * t + 1) * d_[i] + (3 * t2 - 2 * t) * d_[i + 1];
}

double MonotoneTable::operator()(double x) const {
  double y, dy;
  evaluate(x, y, dy);
  return y;
}

}  // namespace rollspec::beam
