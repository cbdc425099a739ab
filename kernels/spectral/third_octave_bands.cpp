#include "kernels/spectral/third_octave_bands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollspec::spectral {

namespace {
// IEC 61260-1 Annex E nominal midband frequencies for one decade (x = 0..9 from 1000 Hz).
constexpr double kNominalDecade[10] = {1.0, 1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0};
}  // namespace

Band third_octave_band(int index) {
  Band b{};
  b.index = index;
  b.centre = 1000.0 * std::pow(10.0, index / 10.0);
  b.lower = b.centre * std::pow(10.0, -1.0 / 20.0);
  b.upper = b.centre * std::pow(10.0, 1.0 / 20.0);
  const int decade = static_cast<int>(std::floor(index / 10.0));
  const int within = index - 10 * decade;
  b.nominal = kNominalDecade[within] * 1000.0 * std::pow(10.0, decade);
  return b;
}

std::vector<Band> third_octave_bands(double f_min, double f_max) {
  if (!(f_min > 0.0) || !(f_max > f_min)) throw std::invalid_argument("third-octave range needs 0 < f_min < f_max");
  std::vector<Band> out;
  int first = static_cast<int>(std::floor(10.0 * std::log10(f_min / 1000.0))) - 1;
  for (int x = first;; ++x) {
    Band b = third_octave_band(x);
    if (b.lower < f_min * (1.0 - 1e-12)) continue;
    if (b.upper > f_max * (1.0 + 1e-12)) break;
    out.push_back(b);
  }
  return out;
}

double band_bins(double df, double lower, double upper) { return (upper - lower) / df; }

double band_average(const double* psd, std::size_t n, double df, double lower, double upper) {
  if (!(upper > lower)) throw std::invalid_argument("band upper edge must exceed lower edge");
  double acc = 0.0;
  const auto k0 = static_cast<std::size_t>(std::max(0.0, std::floor(lower / df - 0.5)));
  for (std::size_t k = k0; k < n; ++k) {
    const double a = (static_cast<double>(k) - 0.5) * df, b = (static_cast<double>(k) + 0.5) * df;
    if (a >= upper) break;
    const double overlap = std::min(b, upper) - std::max(a, lower);
    if (overlap > 0.0) acc += psd[k] * overlap;
  }
  return acc / (upper - lower);
}

double band_average_irregular(const double* f, const double* psd, std::size_t n, double lower, double upper) {
  if (n < 2 || f[0] > lower || f[n - 1] < upper) return std::nan("");
  double acc = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double a = std::max(f[i], lower), b = std::min(f[i + 1], upper);
    if (b <= a) continue;
    // Trapezoid of the linear interpolant over [a, b] inside [f_i, f_i+1].
    const double slope = (psd[i + 1] - psd[i]) / (f[i + 1] - f[i]);
    const double pa = psd[i] + slope * (a - f[i]), pb = psd[i] + slope * (b - f[i]);
    acc += 0.5 * (pa + pb) * (b - a);
  }
  return acc / (upper - lower);
}

double band_rule_shift(const double* psd, std::size_t n, double df, double lower, double upper) {
  std::vector<double> f(n);
  for (std::size_t k = 0; k < n; ++k) f[k] = df * static_cast<double>(k);
  return std::log(band_average_irregular(f.data(), psd, n, lower, upper) / band_average(psd, n, df, lower, upper));
}

}  // namespace rollspec::spectral
