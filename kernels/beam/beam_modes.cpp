#include "kernels/beam/beam_modes.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rollspec::beam {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double clamped_clamped_root(int n) {
  if (n < 1) throw std::invalid_argument("clamped_clamped_root: mode number must be >= 1");
  // f(x) = cos x - sech x (B1): same roots as cos x cosh x = 1, but bounded, so Newton's
  // steps stay meaningful for any n. Root in (c - pi/4, c + pi/4), c = (n + 1/2) pi (B2).
  const double c = (n + 0.5) * pi;
  double lo = c - 0.25 * pi, hi = c + 0.25 * pi;
  auto f = [](double x) { return std::cos(x) - 1.0 / std::cosh(x); };
  auto df = [](double x) { return -std::sin(x) + std::tanh(x) / std::cosh(x); };
  const double flo = f(lo);
  double x = c;
  // Last-ulp polish: move to the neighbouring double while it lowers |f| (root to within 1/2 ulp).
  auto polish = [&](double r) {
    for (int k = 0; k < 8; ++k) {
      const double up = std::nextafter(r, hi + 1.0), dn = std::nextafter(r, lo - 1.0);
      const double fr = std::abs(f(r));
      if (std::abs(f(up)) < fr)
        r = up;
      else if (std::abs(f(dn)) < fr)
        r = dn;
      else
        break;
    }
    return r;
  };
  for (int it = 0; it < 200; ++it) {
    const double fx = f(x);
    if (fx == 0.0) return x;
    // Keep the bracket: the sign of f at lo is known.
    if ((fx > 0.0) == (flo > 0.0))
      lo = x;
    else
      hi = x;
    double xn = x - fx / df(x);
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(xn - x) <= 2.0 * std::numeric_limits<double>::epsilon() * x) return polish(xn);
    x = xn;
    if (hi - lo <= 2.0 * std::numeric_limits<double>::epsilon() * x) return polish(x);
  }
  return polish(x);
}

double wavenumber_length(Support support, int n) {
  if (n < 1) throw std::invalid_argument("wavenumber_length: mode number must be >= 1");
  return support == Support::clamped_clamped ? clamped_clamped_root(n) : n * pi;
}

ModeShape::ModeShape(Support support, int n, double length) : support_(support), n_(n), l_(length) {
  if (!(length > 0.0)) throw std::invalid_argument("ModeShape: length must be > 0");
  const double kl = wavenumber_length(support, n);
  k_ = kl / length;
  if (support == Support::clamped_clamped) {
    // (B3): 1 - sigma = (cos kl - sin kl - e^{-kl}) / (sinh kl - sin kl), computed without
    // subtracting nearly equal numbers; A = (1/2)(1 - sigma) e^{kl}.
    const double e = std::exp(-kl), s = std::sin(kl), c = std::cos(kl);
    a_ = (c - s - e) / (1.0 - e * e - 2.0 * s * e);
    sigma_ = 1.0 - 2.0 * a_ * e;
    mirror_ = (n % 2 == 1) ? 1.0 : -1.0;
  }
}

double ModeShape::value(double x) const { return evaluate(x).value; }

ShapeValues ModeShape::evaluate(double x) const {
  if (support_ == Support::simply_supported) {
    const double s = std::sqrt(2.0), kx = k_ * x;
    return {s * std::sin(kx), s * k_ * std::cos(kx), -s * k_ * k_ * std::sin(kx)};
  }
  // Mirror to the left half (B5): phi(l - y) = m phi(y), phi'(l - y) = -m phi'(y), phi'' likewise m.
  double y = x, m = 1.0, ms = 1.0;
  if (x > 0.5 * l_) {
    y = l_ - x;
    m = mirror_;
    ms = -mirror_;
  }
  const double ky = k_ * y;
  const double ep = a_ * std::exp(k_ * (y - l_));          // (1/2)(1-sigma) e^{ky}
  const double em = 0.5 * (1.0 + sigma_) * std::exp(-ky);  // (1/2)(1+sigma) e^{-ky}
  const double c = std::cos(ky), s = std::sin(ky);
  const double v = ep + em - c + sigma_ * s;
  const double d = ep - em + s + sigma_ * c;
  const double dd = ep + em + c - sigma_ * s;
  return {m * v, ms * k_ * d, m * k_ * k_ * dd};
}

}  // namespace rollspec::beam
