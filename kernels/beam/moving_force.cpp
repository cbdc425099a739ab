#include "kernels/beam/moving_force.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/integrators/exact_oscillator_step.hpp"

namespace rollspec::beam {

std::vector<std::vector<double>> moving_force_deflection(const ModalBeam& b, double x_start, double speed,
                                                         const std::vector<double>& force, double dt,
                                                         const std::vector<double>& positions) {
  const int n = b.modes();
  const double m = b.modal_mass();
  std::vector<integrators::ExactOscillatorStep> osc;
  for (int i = 0; i < n; ++i) osc.push_back(integrators::ExactOscillatorStep::make(b.omega(i), b.zeta(i), dt));
  std::vector<double> pp(positions.size() * n);
  for (std::size_t p = 0; p < positions.size(); ++p) b.shapes(positions[p], pp.data() + p * n);
  std::vector<std::vector<double>> w(positions.size(), std::vector<double>(force.size(), 0.0));
  std::vector<double> q(n, 0.0), v(n, 0.0), phi0(n), phi1(n);
  if (force.empty()) return w;
  b.shapes(x_start, phi0.data());
  for (std::size_t k = 0; k + 1 < force.size(); ++k) {
    b.shapes(x_start + speed * (static_cast<double>(k + 1) * dt), phi1.data());
    for (int i = 0; i < n; ++i) osc[i].advance(q[i], v[i], -phi0[i] * force[k] / m, -phi1[i] * force[k + 1] / m);
    for (std::size_t p = 0; p < positions.size(); ++p) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += pp[p * n + i] * q[i];
      w[p][k + 1] = s;
    }
    phi0.swap(phi1);
  }
  return w;
}

double fryba_moving_force(double l, double ei, double mu, double p, double speed, double x, double t, int terms) {
  const double pi = 3.14159265358979323846;
  const double w1 = pi * pi / (l * l) * std::sqrt(ei / mu);
  const double w = pi * speed / l, alpha = w / w1;
  const double w0 = 2.0 * p * l * l * l / (pi * pi * pi * pi * ei);
  double s = 0.0;
  for (int j = 1; j <= terms; ++j) {
    const double jj = j * j;
    if (std::abs(jj - alpha * alpha) < 1e-12) throw std::invalid_argument("fryba_moving_force: resonant speed");
    s += (std::sin(j * w * t) - alpha / j * std::sin(jj * w1 * t)) * std::sin(j * pi * x / l) /
         (jj * (jj - alpha * alpha));
  }
  return w0 * s;
}

}  // namespace rollspec::beam
