#include "kernels/texture/tabulated_psd.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rollspec::texture {

namespace {
std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}
}  // namespace

TabulatedPsd::TabulatedPsd(std::vector<double> wavenumber, std::vector<double> psd, Extension extension)
    : k_(std::move(wavenumber)), g_(std::move(psd)), extension_(extension) {
  if (k_.size() != g_.size())
    throw std::invalid_argument("PSD table: " + std::to_string(k_.size()) + " abscissae but " +
                                std::to_string(g_.size()) + " values");
  if (k_.size() < 2) throw std::invalid_argument("PSD table needs at least 2 points, got " + std::to_string(k_.size()));
  for (std::size_t i = 0; i < k_.size(); ++i) {
    if (!std::isfinite(k_[i]) || !(k_[i] > 0.0))
      throw std::invalid_argument("PSD table: abscissa at index " + std::to_string(i) + " is " + num(k_[i]) +
                                  " (must be finite and > 0)");
    if (i > 0 && !(k_[i] > k_[i - 1]))
      throw std::invalid_argument("PSD table: abscissae must be strictly increasing, but index " + std::to_string(i) +
                                  " (" + num(k_[i]) + ") <= index " + std::to_string(i - 1) + " (" + num(k_[i - 1]) +
                                  ")");
    if (!std::isfinite(g_[i]) || g_[i] < 0.0)
      throw std::invalid_argument("PSD table: value at index " + std::to_string(i) + " is " + num(g_[i]) +
                                  " (must be finite and >= 0)");
  }
  if (extension_ == Extension::power_law &&
      (g_.front() <= 0.0 || g_[1] <= 0.0 || g_.back() <= 0.0 || g_[g_.size() - 2] <= 0.0))
    throw std::invalid_argument("PSD table: power-law extension needs positive values in the first and last segments");
}

double TabulatedPsd::segment(std::size_t i, double k) const {
  const double k0 = k_[i], k1 = k_[i + 1], g0 = g_[i], g1 = g_[i + 1];
  if (g0 <= 0.0 || g1 <= 0.0) return g0 + (g1 - g0) * (k - k0) / (k1 - k0);  // linear where log is undefined
  const double s = std::log(g1 / g0) / std::log(k1 / k0);                    // Eq. 5
  return g0 * std::pow(k / k0, s);
}

double TabulatedPsd::operator()(double k) const {
  const std::size_t n = k_.size();
  if (k >= k_.front() && k <= k_.back()) {
    if (k == k_.back()) return g_.back();
    const auto it = std::upper_bound(k_.begin(), k_.end(), k);
    return segment(static_cast<std::size_t>(it - k_.begin()) - 1, k);
  }
  const bool below = k < k_.front();
  switch (extension_) {
    case Extension::constant:
      return below ? g_.front() : g_.back();
    case Extension::zero:
      return 0.0;
    case Extension::power_law:
      return below ? segment(0, k) : segment(n - 2, k);
    case Extension::error:
      break;
  }
  throw std::domain_error("PSD table covers k = " + num(k_.front()) + " .. " + num(k_.back()) +
                          " rad/m; asked for k = " + num(k) + " rad/m and no extension is set");
}

double TabulatedPsd::integral(double a, double b) const {
  double acc = 0.0;
  for (std::size_t i = 0; i + 1 < k_.size(); ++i) {
    const double lo = std::max(a, k_[i]), hi = std::min(b, k_[i + 1]);
    if (!(hi > lo)) continue;
    const double k0 = k_[i], g0 = g_[i], g1 = g_[i + 1];
    if (g0 <= 0.0 || g1 <= 0.0) {  // linear segment: the trapezoid is exact
      acc += 0.5 * (segment(i, lo) + segment(i, hi)) * (hi - lo);
      continue;
    }
    const double s1 = std::log(g1 / g0) / std::log(k_[i + 1] / k0) + 1.0;  // Eq. 5 integrated
    acc += std::abs(s1) < 1e-12 ? g0 * k0 * std::log(hi / lo)
                                : g0 * k0 / s1 * (std::pow(hi / k0, s1) - std::pow(lo / k0, s1));
  }
  return acc;
}

Psd TabulatedPsd::to_psd() const {
  Psd p;
  const TabulatedPsd copy = *this;
  p.density = [copy](double k) { return copy(k); };
  p.breakpoints = k_;  // log-log interpolation kinks at every node
  p.support_min = (extension_ == Extension::zero) ? k_.front() : 0.0;
  p.support_max = (extension_ == Extension::zero || extension_ == Extension::error)
                      ? k_.back()
                      : std::numeric_limits<double>::infinity();
  p.description = "tabulated PSD, " + std::to_string(k_.size()) + " points, k = " + num(k_.front()) + " .. " +
                  num(k_.back()) + " rad/m";
  return p;
}

}  // namespace rollspec::texture
