#include "kernels/beam/uniform_samples.hpp"

#include <cmath>
#include <stdexcept>

namespace rollspec::beam {

void UniformSamples::evaluate(double x, double& value, double& derivative) const {
  const std::size_t n = values.size();
  if (n < 2 || !(step > 0.0)) throw std::invalid_argument("UniformSamples: need >= 2 samples and step > 0");
  double u = (x - origin) / step;
  const double last = static_cast<double>(n - 1);
  if (!(u >= -1e-9 && u <= last + 1e-9)) throw std::out_of_range("UniformSamples: position outside the sampled range");
  u = std::min(std::max(u, 0.0), last);
  std::size_t i = static_cast<std::size_t>(u);
  if (i >= n - 1) i = n - 2;
  const double t = u - static_cast<double>(i);
  const double y0 = values[i], y1 = values[i + 1];
  // Catmull–Rom slopes in units of "per sample" (B13).
  const double m0 = i > 0 ? 0.5 * (y1 - values[i - 1]) : y1 - y0;
  const double m1 = i + 2 < n ? 0.5 * (values[i + 2] - y0) : y1 - y0;
  const double t2 = t * t, t3 = t2 * t;
  value = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1;
  derivative = ((6 * t2 - 6 * t) * y0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * y1 + (3 * t2 - 2 * t) * m1) / step;
}

double UniformSamples::value(double x) const {
  double v, d;
  evaluate(x, v, d);
  return v;
}

}  // namespace rollspec::beam
