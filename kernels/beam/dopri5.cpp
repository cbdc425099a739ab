#include "kernels/beam/dopri5.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollspec::beam {

Dopri5Stats dopri5(const OdeRhs& f, std::vector<double> y, double t0, const std::vector<double>& outputs,
                   const OdeObserver& observe, const Dopri5Options& opt) {
  const std::size_t n = y.size();
  if (opt.atol.size() != n) throw std::invalid_argument("dopri5: atol must have one entry per component");
  if (outputs.empty()) return {};
  // Butcher tableau (Dormand & Prince 1980).
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784, a76 = 11.0 / 84;
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                   e7 = -1.0 / 40;
  // Dense output (Hairer's contd5).
  constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                   d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                   d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

  std::vector<double> k1(n), k2(n), k3(n), k4(n), k5(n), k6(n), k7(n), yt(n), y1(n), yd(n);
  std::vector<double> r1(n), r2(n), r3(n), r4(n), r5(n);
  Dopri5Stats st;
  double t = t0;
  const double t_end = outputs.back();
  std::size_t j = 0;
  while (j < outputs.size() && outputs[j] <= t0) observe(j, outputs[j], y.data()), ++j;
  f(t, y.data(), k1.data());
  ++st.evaluations;
  auto sc = [&](std::size_t i, double a, double b) {
    return opt.atol[i] + opt.rtol * std::max(std::abs(a), std::abs(b));
  };
  double h = opt.initial_step;
  if (!(h > 0.0)) {  // Hairer's starting step rule (II.4)
    double d0 = 0, dd1 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double s = sc(i, y[i], y[i]);
      d0 += (y[i] / s) * (y[i] / s);
      dd1 += (k1[i] / s) * (k1[i] / s);
    }
    d0 = std::sqrt(d0 / static_cast<double>(n));
    dd1 = std::sqrt(dd1 / static_cast<double>(n));
    h = (d0 < 1e-5 || dd1 < 1e-5) ? 1e-6 : 0.01 * d0 / dd1;
    h = std::min(h, t_end - t0);
  }
  if (opt.max_step > 0.0) h = std::min(h, opt.max_step);
  while (j < outputs.size()) {
    if (st.accepted + st.rejected >= opt.max_steps) throw std::runtime_error("dopri5: too many steps");
    const bool last = t + h >= t_end;
    if (last) h = t_end - t;
    for (std::size_t i = 0; i < n; ++i) yt[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, yt.data(), k2.data());
    for (std::size_t i = 0; i < n; ++i) yt[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    f(t + c3 * h, yt.data(), k3.data());
    for (std::size_t i = 0; i < n; ++i) yt[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    f(t + c4 * h, yt.data(), k4.data());
    for (std::size_t i = 0; i < n; ++i) yt[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + c5 * h, yt.data(), k5.data());
    for (std::size_t i = 0; i < n; ++i)
      yt[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + h, yt.data(), k6.data());
    for (std::size_t i = 0; i < n; ++i)
      y1[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    f(t + h, y1.data(), k7.data());
    st.evaluations += 6;
    double err = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
      const double s = sc(i, y[i], y1[i]);
      err += (e / s) * (e / s);
    }
    err = std::sqrt(err / static_cast<double>(n));
    if (!std::isfinite(err)) err = 1e10;
    const double fac = std::min(10.0, std::max(0.2, 0.9 * std::pow(std::max(err, 1e-300), -0.2)));
    if (err <= 1.0) {
      ++st.accepted;
      const double tn = last ? t_end : t + h;
      // Dense output between t and tn for every output inside.
      bool dense_ready = false;
      while (j < outputs.size() && outputs[j] <= tn) {
        if (!dense_ready) {
          for (std::size_t i = 0; i < n; ++i) {
            const double ydiff = y1[i] - y[i], bspl = h * k1[i] - ydiff;
            r1[i] = y[i];
            r2[i] = ydiff;
            r3[i] = bspl;
            r4[i] = ydiff - h * k7[i] - bspl;
            r5[i] = h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * k7[i]);
          }
          dense_ready = true;
        }
        const double th = (outputs[j] - t) / h, th1 = 1.0 - th;
        for (std::size_t i = 0; i < n; ++i) yd[i] = r1[i] + th * (r2[i] + th1 * (r3[i] + th * (r4[i] + th1 * r5[i])));
        observe(j, outputs[j], yd.data());
        ++j;
      }
      y.swap(y1);
      k1.swap(k7);  // FSAL
      t = tn;
      h *= fac;
    } else {
      ++st.rejected;
      h *= std::min(1.0, fac);
    }
    if (opt.max_step > 0.0) h = std::min(h, opt.max_step);
    if (!(h > 1e-14 * std::max(1.0, std::abs(t)))) throw std::runtime_error("dopri5: step size underflow");
  }
  return st;
}

}  // namespace rollspec::beam
