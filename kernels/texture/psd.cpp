#include "kernels/texture/psd.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernels/texture/gauss_panel.hpp"

namespace rollspec::texture {

namespace {
// Eq. 14b: (1/dk) times the integral of G over [lo, hi], in panels between the breakpoints (sorted).
double cell_mean(const Psd& psd, const std::vector<double>& breaks, double lo, double hi) {
  double acc = 0.0, a = lo;
  auto it = std::upper_bound(breaks.begin(), breaks.end(), lo);
  while (a < hi) {
    double b = hi;
    if (it != breaks.end() && *it < hi) b = *it++;
    if (b > a) acc += gauss_panel(a, b, [&](double k) { return psd(k); });
    a = b;
  }
  return acc / (hi - lo);
}
}  // namespace

std::vector<double> psd_at_harmonics(const Psd& psd, double dk, std::size_t count) {
  if (!(dk > 0.0) || !std::isfinite(dk)) throw std::invalid_argument("harmonic spacing dk must be positive and finite");
  std::vector<double> g(count, 0.0);
  std::vector<double> breaks;
  if (psd.cell_average) {
    breaks = psd.breakpoints;
    for (double b : {psd.support_min, psd.support_max})
      if (b > 0.0 && std::isfinite(b)) breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
  }
  for (std::size_t j = 1; j < count; ++j) {
    const double k = dk * static_cast<double>(j);
    // The cell's lower half below the table's first node reads the extension (zero: no power).
    const double v = psd.cell_average ? cell_mean(psd, breaks, k - 0.5 * dk, k + 0.5 * dk) : psd(k);
    if (!(v >= 0.0) || !std::isfinite(v))
      throw std::domain_error("PSD value at k = " + std::to_string(k) + " rad/m is " + std::to_string(v) +
                              " (must be finite and >= 0)");
    g[j] = v;
  }
  return g;
}

Psd band_limited(Psd psd, double k_max) {
  if (!(k_max > 0.0)) throw std::invalid_argument("band limit k_max must be positive");
  if (!(k_max < psd.support_max)) return psd;
  psd.density = [g = std::move(psd.density), k_max](double k) { return k > k_max ? 0.0 : g(k); };
  psd.support_max = k_max;
  psd.breakpoints.push_back(k_max);
  psd.description += ", band-limited to k <= " + std::to_string(k_max) + " rad/m";
  return psd;
}

Psd interpolation_compensated(Psd psd, double dx) {
  if (!(dx > 0.0) || !(psd.support_max * dx < M_PI))
    throw std::invalid_argument("interpolation_compensated needs a PSD band-limited below pi/dx");
  psd.density = [g = std::move(psd.density), dx](double k) {
    const double x = 0.5 * k * dx;
    const double sinc = x < 1e-8 ? 1.0 : std::sin(x) / x;
    return g(k) / (sinc * sinc * sinc * sinc);
  };
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", dx);
  psd.description += ", compensated for the linear interpolant at dx = " + std::string(buf) + " m";
  return psd;
}

double integrate_psd(const Psd& psd, double k0, double k1, double p, std::size_t points) {
  if (!(k0 > 0.0) || !(k1 > k0) || points < 2)
    throw std::invalid_argument("integrate_psd needs 0 < k0 < k1, >= 2 points");
  const double r = std::log(k1 / k0) / static_cast<double>(points - 1);
  double acc = 0.0, prev_k = k0, prev_f = std::pow(k0, p) * psd(k0);
  for (std::size_t i = 1; i < points; ++i) {
    const double k = (i + 1 == points) ? k1 : k0 * std::exp(r * static_cast<double>(i));
    const double f = std::pow(k, p) * psd(k);
    acc += 0.5 * (f + prev_f) * (k - prev_k);
    prev_k = k;
    prev_f = f;
  }
  return acc;
}

}  // namespace rollspec::texture
