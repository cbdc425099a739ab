#include "kernels/beam/linear_response.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace rollspec::beam {

LinearResponse linear_response_psd(const ModalBeam& b, double m2, double k0, double c0,
                                   const std::vector<double>& xi, const std::vector<double>& sensors,
                                   const std::vector<double>& freq, const std::vector<double>& gx, Excitation kind) {
  if (freq.size() != gx.size()) throw std::invalid_argument("linear_response_psd: frequencies and PSD differ in length");
  if (xi.empty()) throw std::invalid_argument("linear_response_psd: no contact positions");
  if (!(m2 > 0.0 && k0 > 0.0 && c0 >= 0.0)) throw std::invalid_argument("linear_response_psd: need m2 > 0, k0 > 0, c0 >= 0");
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
  std::vector<cd> modal(n), alpha_s(sensors.size());
  const double inv = 1.0 / static_cast<double>(xi.size());
  for (std::size_t k = 0; k < freq.size(); ++k) {
    const double w = two_pi * freq[k];
    if (!(w > 0.0)) continue;
    for (int i = 0; i < n; ++i) {
      const double wn = b.omega(i);
      modal[i] = 1.0 / (m * cd(wn * wn - w * w, 2.0 * b.zeta(i) * wn * w));
    }
    const cd kc(k0, w * c0);
    const double alpha_ball = -1.0 / (m2 * w * w);
    for (std::size_t p = 0; p < xi.size(); ++p) {
      const double* pc = phi_c.data() + p * n;
      cd alpha_b = 0.0;
      for (std::size_t s = 0; s < sensors.size(); ++s) alpha_s[s] = 0.0;
      for (int i = 0; i < n; ++i) {
        alpha_b += pc[i] * pc[i] * modal[i];
        for (std::size_t s = 0; s < sensors.size(); ++s) alpha_s[s] += phi_s[s * n + i] * pc[i] * modal[i];
      }
      // (B32); the residual compliance is quasi-static: the damper does not see its rate (B21),
      // so it enters with the elastic share k0 / (k0 + i w c0), exactly as in the time domain.
      cd total = 1.0 / kc + alpha_b + alpha_ball + res[p] * k0 / kc;
      if (kind == Excitation::blocked_force) total *= kc;
      const double f2 = 1.0 / std::norm(total);  // |F / excitation|^2
      out.force_psd[k] += inv * f2 * gx[k];
      for (std::size_t s = 0; s < sensors.size(); ++s)
        out.sensor_psd[s][k] += inv * std::norm(w * w * alpha_s[s]) * f2 * gx[k];  // (B33), (B34)
    }
  }
  return out;
}

}  // namespace rollspec::beam
