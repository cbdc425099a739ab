#include "kernels/texture/self_affine_psd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

namespace {
// Integrals of the unit-plateau shape, Eq. 7 and 8 with C = 1.
double shape_integral_height(const SelfAffineSpec& s) {
  const double a = 1.0 + 2.0 * s.hurst, rho = s.k_short / s.k_rolloff;
  return (s.k_rolloff - s.k_long) + s.k_rolloff * (1.0 - std::pow(rho, 1.0 - a)) / (a - 1.0);
}
double shape_integral_slope(const SelfAffineSpec& s) {
  const double a = 1.0 + 2.0 * s.hurst, rho = s.k_short / s.k_rolloff, kr3 = std::pow(s.k_rolloff, 3);
  const double tail =
      (std::abs(3.0 - a) < 1e-12) ? kr3 * std::log(rho) : kr3 * (std::pow(rho, 3.0 - a) - 1.0) / (3.0 - a);
  return (kr3 - std::pow(s.k_long, 3)) / 3.0 + tail;
}
}  // namespace

SelfAffinePsd::SelfAffinePsd(const SelfAffineSpec& s) : spec(s) {
  if (!(s.hurst > 0.0 && s.hurst <= 1.0))
    throw std::invalid_argument("self-affine PSD: Hurst exponent must be in (0, 1], got " + std::to_string(s.hurst));
  if (!(s.k_long >= 0.0) || !std::isfinite(s.k_long))
    throw std::invalid_argument("self-affine PSD: long cut-off k_l must be finite and >= 0");
  if (!(s.k_rolloff > 0.0) || !(s.k_rolloff >= s.k_long))
    throw std::invalid_argument("self-affine PSD: roll-off k_r must be > 0 and >= k_l (k_l = " +
                                std::to_string(s.k_long) + ", k_r = " + std::to_string(s.k_rolloff) + ")");
  if (!(s.k_short > s.k_rolloff) || !std::isfinite(s.k_short))
    throw std::invalid_argument("self-affine PSD: short cut-off k_s must be finite and > k_r (k_r = " +
                                std::to_string(s.k_rolloff) + ", k_s = " + std::to_string(s.k_short) + ")");
  if (!(s.rms > 0.0) || !std::isfinite(s.rms))
    throw std::invalid_argument("self-affine PSD: target rms must be positive and finite");
  const double integral = (s.target == RmsTarget::height) ? shape_integral_height(s) : shape_integral_slope(s);
  c = s.rms * s.rms / integral;
}

double SelfAffinePsd::operator()(double k) const {
  if (k < spec.k_long || k > spec.k_short) return 0.0;
  if (k < spec.k_rolloff) return c;
  return c * std::pow(k / spec.k_rolloff, -(1.0 + 2.0 * spec.hurst));
}

double SelfAffinePsd::rms_height() const { return std::sqrt(c * shape_integral_height(spec)); }
double SelfAffinePsd::rms_slope() const { return std::sqrt(c * shape_integral_slope(spec)); }

Psd SelfAffinePsd::to_psd() const {
  Psd p;
  const SelfAffinePsd copy = *this;
  p.density = [copy](double k) { return copy(k); };
  p.support_min = spec.k_long;
  p.support_max = spec.k_short;
  p.breakpoints = {spec.k_rolloff, spec.k_short};
  if (spec.k_long > 0.0) p.breakpoints.insert(p.breakpoints.begin(), spec.k_long);
  p.description = "self-affine PSD, H = " + std::to_string(spec.hurst) +
                  ", k_l/k_r/k_s = " + std::to_string(spec.k_long) + "/" + std::to_string(spec.k_rolloff) + "/" +
                  std::to_string(spec.k_short) + " rad/m";
  return p;
}

}  // namespace rollspec::texture
