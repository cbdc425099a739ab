#include "kernels/beam/contact_patch_filter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollspec::beam {

UniformSamples contact_patch_average(const UniformSamples& h, double a) {
  const std::size_t n = h.values.size();
  if (n < 2 || !(h.step > 0.0)) throw std::invalid_argument("contact_patch_average: need >= 2 samples and step > 0");
  if (!(a >= 0.0)) throw std::invalid_argument("contact_patch_average: half width must be >= 0");
  if (a == 0.0) return h;
  // Prefix integral of the linear interpolant at the samples (units of step).
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + 0.5 * (h.values[i - 1] + h.values[i]);
  const double last = static_cast<double>(n - 1);
  auto prefix = [&](double u) {  // integral from 0 to u (sample units), u in [0, n-1]
    u = std::min(std::max(u, 0.0), last);
    std::size_t i = static_cast<std::size_t>(u);
    if (i >= n - 1) i = n - 2;
    const double t = u - static_cast<double>(i);
    return s[i] + t * h.values[i] + 0.5 * t * t * (h.values[i + 1] - h.values[i]);
  };
  const double w = a / h.step;
  UniformSamples out{h.origin, h.step, std::vector<double>(n)};
  for (std::size_t j = 0; j < n; ++j) {
    const double u = static_cast<double>(j);
    const double lo = std::max(u - w, 0.0), hi = std::min(u + w, last);
    out.values[j] = (prefix(hi) - prefix(lo)) / (hi - lo);
  }
  return out;
}

double contact_patch_transfer(double k, double a, double dx) {
  if (!(dx > 0.0) || !(a >= 0.0)) throw std::invalid_argument("contact_patch_transfer: need dx > 0 and a >= 0");
  if (a == 0.0) return 1.0;  // contact_patch_average returns the samples themselves
  const double w = a / dx, theta = k * dx;
  // Antiderivative of the hat Lambda(u) = max(1 - |u|, 0).
  auto hat_integral = [](double x) {
    if (x <= -1.0) return 0.0;
    if (x < 0.0) return 0.5 * (x + 1.0) * (x + 1.0);
    if (x < 1.0) return 1.0 - 0.5 * (1.0 - x) * (1.0 - x);
    return 1.0;
  };
  const auto nmax = static_cast<long>(std::ceil(w)) + 1;
  double t = 0.0;
  for (long n = -nmax; n <= nmax; ++n) {  // (B35a)
    const double c = (hat_integral(w - static_cast<double>(n)) - hat_integral(-w - static_cast<double>(n))) / (2.0 * w);
    t += c * std::cos(static_cast<double>(n) * theta);
  }
  return t;
}

PatchAverager::PatchAverager(const UniformSamples& h) : h_(&h) {
  const std::size_t n = h.values.size();
  if (n < 2 || !(h.step > 0.0)) throw std::invalid_argument("PatchAverager: need >= 2 samples and step > 0");
  s_.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s_[i] = s_[i - 1] + 0.5 * (h.values[i - 1] + h.values[i]);
}

double PatchAverager::prefix(double u) const {
  const std::size_t n = s_.size();
  const std::vector<double>& y = h_->values;
  u = std::min(std::max(u, 0.0), static_cast<double>(n - 1));
  std::size_t i = static_cast<std::size_t>(u);
  if (i >= n - 1) i = n - 2;
  const double t = u - static_cast<double>(i);
  return s_[i] + t * y[i] + 0.5 * t * t * (y[i + 1] - y[i]);
}

void PatchAverager::evaluate(double x, double a, double& value, double& derivative) const {
  const double dx = h_->step;
  if (!(a >= 0.1 * dx)) {
    h_->evaluate(x, value, derivative);
    return;
  }
  const double u = (x - h_->origin) / dx, w = a / dx;
  const double last = static_cast<double>(s_.size() - 1);
  if (!(u >= -1e-9 && u <= last + 1e-9)) throw std::out_of_range("PatchAverager: position outside the sampled range");
  // (B38), the window truncated at the record ends as in contact_patch_average
  const double lo = std::max(u - w, 0.0), hi = std::min(u + w, last);
  value = (prefix(hi) - prefix(lo)) / (hi - lo);
  derivative = (h_->value(h_->origin + hi * dx) - h_->value(h_->origin + lo * dx)) / ((hi - lo) * dx);
}

}  // namespace rollspec::beam
