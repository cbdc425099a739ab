#include "kernels/beam/linear_response.hpp"

#include <cmath>
#include <algorithm>
#include <complex>
#include <stdexcept>

namespace rollspec::beam {

namespace {
// 1 / z without the library's overflow-guarded complex division (__divdc3 was a tenth of the
// reference's time): |z| here is a physical compliance or stiffness, never near overflow.
inline std::complex<double> reciprocal(std::complex<double> z) {
  const double d = 1.0 / (z.real() * z.real() + z.imag() * z.imag());
  return {z.real() * d, -z.imag() * d};
}

inline std::complex<double> receptance(const ModalBeam& b, int i, double modal_mass, double w) {
  const double wn = b.omega(i);
  return reciprocal({modal_mass * (wn * wn - w * w), modal_mass * 2.0 * b.zeta(i) * wn * w});
}
}  // namespace

std::vector<std::complex<double>> modal_receptances(const ModalBeam& b, const std::vector<double>& freq) {
  const auto n = static_cast<std::size_t>(b.modes());
  std::vector<std::complex<double>> out(freq.size() * n, 0.0);
  for (std::size_t k = 0; k < freq.size(); ++k) {
    const double w = 6.28318530717958647692 * freq[k];
    if (!(w > 0.0)) continue;
    for (std::size_t i = 0; i < n; ++i) out[k * n + i] = receptance(b, static_cast<int>(i), b.modal_mass(), w);
  }
  return out;
}

LinearResponse linear_response_psd(const ModalBeam& b, double m2, double k0, double c0, const std::vector<double>& xi,
                                   const std::vector<double>& sensors, const std::vector<double>& freq,
                                   const std::vector<double>& gx, Excitation kind, const std::vector<double>& weights) {
  if (freq.size() != gx.size())
    throw std::invalid_argument("linear_response_psd: frequencies and PSD differ in length");
  if (xi.empty()) throw std::invalid_argument("linear_response_psd: no contact positions");
  if (!weights.empty() && weights.size() != xi.size())
    throw std::invalid_argument("linear_response_psd: one weight per contact position");
  if (!(m2 > 0.0 && k0 > 0.0 && c0 >= 0.0))
    throw std::invalid_argument("linear_response_psd: need m2 > 0, k0 > 0, c0 >= 0");
  using cd = std::complex<double>;
  const int n = b.modes();
  const double m = b.modal_mass(), two_pi = 6.28318530717958647692;
  std::vector<double> phi_c(xi.size() * n), res(xi.size()), phi_s(sensors.size() * n);
  for (std::size_t p = 0; p < xi.size(); ++p) {
    b.shapes(xi[p], phi_c.data() + p * n);
    res[p] = b.residual_flexibility(xi[p]);
  }
  for (std::size_t s = 0; s < sensors.size(); ++s) b.shapes(sensors[s], phi_s.data() + s * n);
  LinearResponse out;
  out.sensor_psd.assign(sensors.size(), std::vector<double>(freq.size(), 0.0));
  out.force_psd.assign(freq.size(), 0.0);
  // (B34a) normalised position weights
  std::vector<double> wp(xi.size(), 1.0 / static_cast<double>(xi.size()));
  if (!weights.empty()) {
    double sum = 0.0;
    for (double v : weights) {
      if (!(v >= 0.0)) throw std::invalid_argument("linear_response_psd: weights must be >= 0");
      sum += v;
    }
    if (!(sum > 0.0)) throw std::invalid_argument("linear_response_psd: weights sum to 0");
    for (std::size_t p = 0; p < xi.size(); ++p) wp[p] = weights[p] / sum;
  }
  // Frequencies are independent: each is computed by the same operations on any thread.
  const auto nfreq = static_cast<std::ptrdiff_t>(freq.size());
#pragma omp parallel
  {
    std::vector<cd> modal(n), alpha_s(sensors.size());
#pragma omp for schedule(static)
    for (std::ptrdiff_t kk = 0; kk < nfreq; ++kk) {
      const auto k = static_cast<std::size_t>(kk);
      const double w = two_pi * freq[k];
      if (!(w > 0.0)) continue;
      for (int i = 0; i < n; ++i) modal[i] = receptance(b, i, m, w);
      const cd kc(k0, w * c0), inv_kc = reciprocal(kc);
      const double alpha_ball = -1.0 / (m2 * w * w);
      for (std::size_t p = 0; p < xi.size(); ++p) {
        const double inv = wp[p];
        if (inv == 0.0) continue;
        const double* pc = phi_c.data() + p * n;
        cd alpha_b = 0.0;
        for (std::size_t s = 0; s < sensors.size(); ++s) alpha_s[s] = 0.0;
        for (int i = 0; i < n; ++i) {
          alpha_b += pc[i] * pc[i] * modal[i];
          for (std::size_t s = 0; s < sensors.size(); ++s) alpha_s[s] += phi_s[s * n + i] * pc[i] * modal[i];
        }
        // (B32); the residual compliance is quasi-static: the damper does not see its rate (B21),
        // so it enters with the elastic share k0 / (k0 + i w c0), exactly as in the time domain.
        cd total = inv_kc + alpha_b + alpha_ball + res[p] * k0 * inv_kc;
        if (kind == Excitation::blocked_force) total *= kc;
        const double f2 = 1.0 / std::norm(total);  // |F / excitation|^2
        out.force_psd[k] += inv * f2 * gx[k];
        for (std::size_t s = 0; s < sensors.size(); ++s)
          out.sensor_psd[s][k] += inv * std::norm(w * w * alpha_s[s]) * f2 * gx[k];  // (B33), (B34)
      }
    }
  }
  return out;
}

std::vector<std::vector<std::complex<double>>> linear_response_transfer(
    const ModalBeam& b, double m2, double k0, double c0, double xi, const std::vector<double>& sensors,
    const std::vector<double>& freq, Excitation kind, const std::vector<std::complex<double>>* modal) {
  if (!(m2 > 0.0 && k0 > 0.0 && c0 >= 0.0))
    throw std::invalid_argument("linear_response_transfer: need m2 > 0, k0 > 0, c0 >= 0");
  using cd = std::complex<double>;
  const int n = b.modes();
  const double m = b.modal_mass(), two_pi = 6.28318530717958647692;
  std::vector<double> pc(n), ps(sensors.size() * n);
  b.shapes(xi, pc.data());
  const double res = b.residual_flexibility(xi);
  for (std::size_t s = 0; s < sensors.size(); ++s) b.shapes(sensors[s], ps.data() + s * n);
  std::vector<std::vector<cd>> out(sensors.size(), std::vector<cd>(freq.size(), 0.0));
  std::vector<cd> alpha_s(sensors.size());
  for (std::size_t k = 0; k < freq.size(); ++k) {
    const double w = two_pi * freq[k];
    if (!(w > 0.0)) continue;
    const cd kc(k0, w * c0);
    cd alpha_b = 0.0;
    std::fill(alpha_s.begin(), alpha_s.end(), cd(0.0));
    for (int i = 0; i < n; ++i) {
      const cd r =
          modal ? (*modal)[k * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] : receptance(b, i, m, w);
      alpha_b += pc[i] * pc[i] * r;
      for (std::size_t s = 0; s < sensors.size(); ++s) alpha_s[s] += ps[s * n + i] * pc[i] * r;
    }
    const cd inv_kc = reciprocal(kc);
    cd total = inv_kc + alpha_b - 1.0 / (m2 * w * w) + res * k0 * inv_kc;  // (B32), as linear_response_psd
    if (kind == Excitation::blocked_force) total *= kc;
    const cd inv_total = reciprocal(total);
    for (std::size_t s = 0; s < sensors.size(); ++s) out[s][k] = w * w * alpha_s[s] * inv_total;  // (B33)
  }
  return out;
}

}  // namespace rollspec::beam
