#include "kernels/texture/isotropic_psd.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

namespace {
// 4-point Gauss-Legendre on [-1, 1].
constexpr double kGaussX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kGaussW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
}  // namespace

double IsotropicPsd::g_derivative(std::size_t c, double q) const {
  const double a = q_[c], b = q_[c + 1], ga = g_[c], gb = g_[c + 1];
  if (ga <= 0.0 || gb <= 0.0) return (gb - ga) / (b - a);
  const double s = std::log(gb / ga) / std::log(b / a);
  return s * ga * std::pow(q / a, s) / q;  // d/dq of ga (q/a)^s
}

IsotropicPsd::IsotropicPsd(const Psd& g, double q_min, double q_cap, std::size_t points_per_decade) {
  if (!(q_min > 0.0) || !std::isfinite(q_min)) throw std::invalid_argument("isotropic PSD: q_min must be positive");
  const double q_e = std::isfinite(g.support_max) ? g.support_max : q_cap;
  if (!(q_e > q_min) || !std::isfinite(q_e))
    throw std::invalid_argument("isotropic PSD: the PSD's upper end " + std::to_string(q_e) +
                                " rad/m must exceed q_min = " + std::to_string(q_min) + " rad/m");
  if (points_per_decade < 10) throw std::invalid_argument("isotropic PSD: at least 10 points per decade");
  const auto m =
      static_cast<std::size_t>(std::ceil(std::log10(q_e / q_min) * static_cast<double>(points_per_decade))) + 1;
  // Log grid ending at q_e, with the PSD's breakpoints as extra nodes so no cell straddles a kink
  // (the cell integrals of Eq. 19 are then of smooth integrands, and S's cusps sit on nodes).
  for (std::size_t i = 0; i <= m; ++i)
    q_.push_back((i == m) ? q_e
                          : q_e * std::pow(10.0, -static_cast<double>(m - i) / static_cast<double>(points_per_decade)));
  const double min_gap = 1e-3 * std::log(10.0) / static_cast<double>(points_per_decade);
  for (double b : g.breakpoints) {
    if (!(b > q_.front()) || !(b < q_e)) continue;
    auto it = std::lower_bound(q_.begin(), q_.end(), b);
    if (std::abs(std::log(*it / b)) < min_gap || std::abs(std::log(*(it - 1) / b)) < min_gap)
      continue;  // already a node
    q_.insert(it, b);
  }
  // Cells ending at a breakpoint or at q_e: there S has a one-sided sqrt cusp (a jump of G'
  // at the right node gives S(r) ~ S(b) + c sqrt(b - r)), interpolated in sqrt(b - r).
  cusp_.assign(q_.size(), false);
  cusp_[q_.size() - 2] = true;
  for (double b : g.breakpoints) {
    const auto it = std::lower_bound(q_.begin(), q_.end(), b * (1.0 - 1e-12));
    if (it != q_.end() && it != q_.begin() && std::abs(*it / b - 1.0) < 1e-6)
      cusp_[static_cast<std::size_t>(it - q_.begin()) - 1] = true;
  }
  g_.resize(q_.size());
  for (std::size_t i = 0; i < q_.size(); ++i) {
    g_[i] = g(q_[i]);
    if (!(g_[i] >= 0.0) || !std::isfinite(g_[i])) {
      char buf[96];  // %g: a PSD value of 1e-20 m^3 is not "0.000000"
      std::snprintf(buf, sizeof buf, "isotropic PSD: G(%.6g rad/m) = %.6g m^3", q_[i], g_[i]);
      throw std::invalid_argument(buf);
    }
  }
  jump_ = g_.back();  // G drops to 0 above q_e
  s_.assign(q_.size(), 0.0);
  std::size_t clamped = 0;
  // Each node's integral is independent (the same bits on any thread count); the work shrinks with i.
  const auto nodes = static_cast<std::ptrdiff_t>(q_.size() - 1);
#pragma omp parallel for schedule(dynamic, 8) reduction(+ : clamped)
  for (std::ptrdiff_t ii = 0; ii < nodes; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double r = q_[i];
    double acc = 0.0;
    for (std::size_t c = i; c + 1 < q_.size(); ++c) {
      const double ta = std::acosh(std::max(1.0, q_[c] / r)), tb = std::acosh(q_[c + 1] / r);
      const double h = 0.5 * (tb - ta), mid = 0.5 * (tb + ta);
      for (int k = 0; k < 4; ++k) acc += kGaussW[k] * h * g_derivative(c, r * std::cosh(mid + h * kGaussX[k]));
    }
    s_[i] = -2.0 * M_PI * acc;  // Eq. 19 without the end jump
    if (s_[i] < 0.0) {
      s_[i] = 0.0;
      ++clamped;
    }
  }
  s_.back() = 0.0;  // S(r) ~ -2 pi G'(q_e) acosh(q_e / r) -> 0 as r -> q_e
  clamped_ = static_cast<double>(clamped) / static_cast<double>(q_.size() - 1);
}

double IsotropicPsd::smooth(double q) const {
  if (q >= q_.back()) return 0.0;  // S(q_e) = 0 too
  if (q <= q_.front()) return s_.front();
  const auto it = std::upper_bound(q_.begin(), q_.end(), q);
  const std::size_t c = static_cast<std::size_t>(it - q_.begin()) - 1;
  const double a = q_[c], b = q_[c + 1], sa = s_[c], sb = s_[c + 1];
  if (cusp_[c]) return sb + (sa - sb) * std::sqrt((b - q) / (b - a));
  if (sa <= 0.0 || sb <= 0.0) return sa + (sb - sa) * (q - a) / (b - a);
  return sa * std::pow(q / a, std::log(sb / sa) / std::log(b / a));
}

double IsotropicPsd::operator()(double q) const {
  const double qe = q_.back();
  if (q > qe) return 0.0;
  return smooth(q) + 2.0 * M_PI * jump_ / std::sqrt(qe * qe - q * q);  // Eq. 20
}

double IsotropicPsd::cell_average(double q, double width) const {
  const double qe = q_.back();
  const double a = std::max(0.0, q - 0.5 * width), b = q + 0.5 * width;
  if (a >= qe) return 0.0;
  const double jump_part =
      2.0 * M_PI * jump_ * (std::asin(std::min(b, qe) / qe) - std::asin(a / qe)) / (b - a);  // Eq. 21
  return smooth(q) + jump_part;
}

double IsotropicPsd::forward_line_psd(double q, std::size_t intervals) const {
  const double qe = q_.back();
  if (q >= qe) return 0.0;
  if (intervals % 2) ++intervals;
  const double te = std::acosh(qe / q), h = te / static_cast<double>(intervals);
  double acc = 0.0;
  for (std::size_t i = 0; i <= intervals; ++i) {
    const double t = h * static_cast<double>(i), r = q * std::cosh(t);
    const double w = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    acc += w * smooth(std::min(r, qe)) * r;
  }
  acc *= h / 3.0;
  // Eq. 18 with G = C_1D / pi; the jump term integrates to pi J exactly (int r dr / sqrt((qe^2-r^2)(r^2-q^2)) = pi/2).
  return acc / (M_PI * M_PI) + jump_;
}

}  // namespace rollspec::texture
