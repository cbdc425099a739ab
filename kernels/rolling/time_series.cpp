#include "kernels/rolling/time_series.hpp"

#include <algorithm>
#include <stdexcept>

namespace rollspec::rolling {

double TimeSeries::operator()(double time) const {
  if (t.empty() || t.size() != v.size()) throw std::invalid_argument("TimeSeries: bad table");
  if (time <= t.front()) return v.front();
  if (time >= t.back()) return v.back();
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double w = (time - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - w) * v[k - 1] + w * v[k];
}

}  // namespace rollspec::rolling
