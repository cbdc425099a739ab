#include "kernels/texture/contact_filtered_psd.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/texture/gauss_panel.hpp"
#include "kernels/texture/tabulated_psd.hpp"

namespace rollspec::texture {

namespace {

// W(s) = (sin s / s)^2, the power transfer of Eq. 37.
double power_weight(double s) {
  const double t = flat_punch_transfer(s);
  return t * t;
}

// Panel ends in y for the smooth part of Eq. 39.
std::vector<double> smooth_panels(const IsotropicSpectrum& c, double a, double k, double y_end) {
  std::vector<double> y{0.0, y_end};
  const double y0 = std::min(k > 0.0 ? k : 1e-6 * y_end, y_end);
  for (int i = 1; i <= 4; ++i) y.push_back(0.25 * y0 * i);
  for (double v = y0; v < y_end; v *= 1.15) y.push_back(v);  // C_iso spans decades: geometric panels
  // S has one-sided sqrt cusps at its kinks and at q_e: panels graded geometrically towards them.
  auto grade = [&](double yb) {
    const double d = 0.1 * std::max(yb, y0);
    for (int j = 0; j <= 14; ++j) {
      const double s = d * std::ldexp(1.0, -j);
      y.push_back(yb - s);
      y.push_back(yb + s);
    }
    y.push_back(yb);
  };
  for (double b : c.kinks)
    if (b > k && b < c.q_end) grade(std::sqrt(b * b - k * k));
  grade(y_end);
  y.erase(std::remove_if(y.begin(), y.end(), [&](double v) { return !(v >= 0.0 && v <= y_end); }), y.end());
  std::sort(y.begin(), y.end());
  y.erase(std::unique(y.begin(), y.end()), y.end());
  if (!(a > 0.0)) return y;
  // At most half an oscillation of W per panel: W(a q) has period pi / a in q, and |dq/dy| <= 1.
  const double max_width = 0.5 * M_PI / a;
  std::vector<double> out{y.front()};
  for (std::size_t i = 1; i < y.size(); ++i) {
    const double w = y[i] - y[i - 1];
    const auto n = static_cast<std::size_t>(std::ceil(w / max_width));
    for (std::size_t j = 1; j < n; ++j) out.push_back(y[i - 1] + w * static_cast<double>(j) / static_cast<double>(n));
    out.push_back(y[i]);
  }
  return out;
}

void check(const IsotropicSpectrum& c, double a, double k) {
  if (!(c.q_end > 0.0) || !std::isfinite(c.q_end))
    throw std::invalid_argument("contact-filtered PSD: q_end must be finite and > 0");
  if (!(a >= 0.0) || !std::isfinite(a))
    throw std::invalid_argument("contact-filtered PSD: contact radius must be >= 0");
  if (!(k >= 0.0)) throw std::invalid_argument("contact-filtered PSD: wavenumber must be >= 0");
}

}  // namespace

double flat_punch_transfer(double s) {
  s = std::abs(s);
  return s < 1e-4 ? 1.0 - s * s / 6.0 : std::sin(s) / s;  // (Eq. 37)
}

IsotropicSpectrum isotropic_spectrum(const IsotropicPsd& c, const std::vector<double>& kinks) {
  IsotropicSpectrum s;
  const IsotropicPsd* p = &c;  // the caller keeps c alive as long as the spectrum
  s.smooth = [p](double q) { return p->smooth(q); };
  s.q_end = c.q_end();
  s.jump = c.end_jump();
  s.kinks = kinks;
  return s;
}

double contact_filtered_line_psd(const IsotropicSpectrum& c, double a, double k) {
  check(c, a, k);
  if (k > c.q_end) return 0.0;
  const double y_end = std::sqrt(std::max(c.q_end * c.q_end - k * k, 0.0));
  // Smooth part of Eq. 39.
  double smooth = 0.0;
  if (y_end > 0.0) {
    const std::vector<double> y = smooth_panels(c, a, k, y_end);
    auto f = [&](double v) {
      const double q = std::sqrt(k * k + v * v);
      return c.smooth(std::min(q, c.q_end)) * power_weight(a * q);
    };
    for (std::size_t i = 1; i < y.size(); ++i) smooth += gauss_panel(y[i - 1], y[i], f);
  }
  // Jump part of Eq. 39, y = Y sin(theta): no singularity left. Half an oscillation per panel.
  double jump = 0.0;
  if (c.jump > 0.0) {
    const auto n = static_cast<std::size_t>(std::ceil(2.0 * a * (c.q_end - k) / M_PI)) + 8;
    const double h = 0.5 * M_PI / static_cast<double>(n);
    auto f = [&](double th) {
      const double s = y_end * std::sin(th);
      return power_weight(a * std::sqrt(k * k + s * s));
    };
    for (std::size_t i = 0; i < n; ++i)
      jump += gauss_panel(h * static_cast<double>(i), h * static_cast<double>(i + 1), f);
    jump *= 2.0 * c.jump / M_PI;
  }
  return smooth / (M_PI * M_PI) + jump;
}

double contact_filtered_line_psd_reference(const IsotropicSpectrum& c, double a, double k, std::size_t intervals) {
  check(c, a, k);
  if (intervals < 2) throw std::invalid_argument("contact-filtered PSD reference: at least 2 intervals");
  if (k > c.q_end) return 0.0;
  const double y_end = std::sqrt(std::max(c.q_end * c.q_end - k * k, 0.0));
  const double n = static_cast<double>(intervals), dy = y_end / n, dth = 0.5 * M_PI / n;
  double smooth = 0.0, jump = 0.0;
  for (std::size_t i = 0; i <= intervals; ++i) {  // trapezoid in y (Eq. 38, smooth part)
    const double y = dy * static_cast<double>(i), q = std::sqrt(k * k + y * y);
    const double f = c.smooth(std::min(q, c.q_end)) * power_weight(a * q);
    smooth += (i == 0 || i == intervals) ? 0.5 * f : f;
  }
  for (std::size_t i = 0; i < intervals; ++i) {  // midpoint in theta (jump part)
    const double s = y_end * std::sin(dth * (static_cast<double>(i) + 0.5));
    jump += power_weight(a * std::sqrt(k * k + s * s));
  }
  return smooth * dy / (M_PI * M_PI) + 2.0 * c.jump / M_PI * jump * dth;
}

Psd contact_filtered_psd(const Psd& g, double a, double k_min, double q_cap, double k_max,
                         std::size_t points_per_decade) {
  if (!(a > 0.0) || !std::isfinite(a)) throw std::invalid_argument("contact-filtered PSD: contact radius must be > 0");
  if (!(k_min > 0.0)) throw std::invalid_argument("contact-filtered PSD: k_min must be > 0");
  if (!(k_max > k_min)) throw std::invalid_argument("contact-filtered PSD: k_max must exceed k_min");
  if (points_per_decade < 10) throw std::invalid_argument("contact-filtered PSD: at least 10 points per decade");
  const IsotropicPsd iso(g, 0.5 * k_min, q_cap, 100);
  const IsotropicSpectrum c = isotropic_spectrum(iso, g.breakpoints);
  const double q_e = iso.q_end(), k_end = std::min(q_e, k_max);
  std::vector<double> k;
  const double ppd = static_cast<double>(points_per_decade);
  // Log spacing, but at most pi / (64 a): G_eq ripples with period ~pi/a in k (the ring zeros of
  // Eq. 37 crossing the line y = 0), which log-log interpolation must resolve at large ka.
  const double ratio = std::pow(10.0, 1.0 / ppd), max_step = M_PI / (64.0 * a);
  for (double v = k_min; v < k_end; v = std::min(v * ratio, v + max_step)) k.push_back(v);
  for (double b : g.breakpoints)
    if (b > k_min && b < k_end) k.push_back(b);
  k.push_back(k_end);
  std::sort(k.begin(), k.end());
  k.erase(std::unique(k.begin(), k.end()), k.end());
  std::vector<double> v(k.size());
  for (std::size_t i = 0; i < k.size(); ++i) v[i] = contact_filtered_line_psd(c, a, k[i]);  // Eq. 38
  Psd out = TabulatedPsd(k, v, Extension::zero).to_psd();
  out.support_min = k_min;
  out.support_max = k_end;  // the table's nodes (g's breakpoints among them) are its breakpoints
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", a * 1e6);
  out.description = g.description + ", iso2d contact filter a = " + buf + " um";
  return out;
}

std::vector<double> contact_filtered_psd_at(const Psd& g, double a, const std::vector<double>& k, double q_cap) {
  if (!(a > 0.0) || !std::isfinite(a)) throw std::invalid_argument("contact-filtered PSD: contact radius must be > 0");
  if (k.empty()) return {};
  const double k_min = *std::min_element(k.begin(), k.end());
  if (!(k_min > 0.0)) throw std::invalid_argument("contact-filtered PSD: wavenumbers must be > 0");
  const IsotropicPsd iso(g, 0.5 * k_min, q_cap, 100);
  const IsotropicSpectrum c = isotropic_spectrum(iso, g.breakpoints);
  std::vector<double> out(k.size());
  const auto nk = static_cast<std::ptrdiff_t>(k.size());
#pragma omp parallel for schedule(dynamic, 4)  // independent wavenumbers: the same bits on any thread count
  for (std::ptrdiff_t i = 0; i < nk; ++i)
    out[static_cast<std::size_t>(i)] = contact_filtered_line_psd(c, a, k[static_cast<std::size_t>(i)]);  // Eq. 38
  return out;
}

}  // namespace rollspec::texture
