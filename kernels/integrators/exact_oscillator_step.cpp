#include "kernels/integrators/exact_oscillator_step.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace rollspec::integrators {

ExactOscillatorStep ExactOscillatorStep::make(double omega, double zeta, double h) {
  if (!(omega >= 0.0) || !(zeta >= 0.0) || !(h > 0.0) || !std::isfinite(omega * zeta * h))
    throw std::invalid_argument("oscillator step needs omega >= 0, zeta >= 0, h > 0, all finite");
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 1) = 1.0;
  m(1, 0) = -omega * omega;
  m(1, 1) = -2.0 * zeta * omega;
  m(1, 2) = 1.0;
  m(2, 3) = 1.0;
  const Eigen::Matrix4d e = (m * h).exp();
  // z(h) = e z(0) with z(0) = [q0, v0, f0, (f1 - f0)/h]: split the force columns into f0 and f1.
  ExactOscillatorStep s{};
  s.a00 = e(0, 0);
  s.a01 = e(0, 1);
  s.a10 = e(1, 0);
  s.a11 = e(1, 1);
  s.b0 = e(0, 2) - e(0, 3) / h;
  s.b1 = e(0, 3) / h;
  s.c0 = e(1, 2) - e(1, 3) / h;
  s.c1 = e(1, 3) / h;
  return s;
}

ExactOscillatorStep exact_oscillator_step_closed_form(double omega, double zeta, double h) {
  if (!(omega > 0.0) || !(zeta >= 0.0 && zeta < 1.0))
    throw std::invalid_argument("closed form needs omega > 0, 0 <= zeta < 1");
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  const double decay = std::exp(-zeta * omega * h);
  const double cs = std::cos(wd * h), sn = std::sin(wd * h);
  ExactOscillatorStep s{};
  // Free response: e^{Ah} = e^{-zeta w h} [cos(wd h) I + sin(wd h)/wd (A + zeta w I)].
  s.a00 = decay * (cs + zeta * omega * sn / wd);
  s.a01 = decay * sn / wd;
  s.a10 = -decay * omega * omega * sn / wd;
  s.a11 = decay * (cs - zeta * omega * sn / wd);
  // Particular solution for f = f0 + r t: q_p = alpha + beta t, beta = r/w^2, alpha = (f0 - 2 zeta w beta)/w^2.
  const double k = omega * omega, c = 2.0 * zeta * omega;
  const double da_df0 = 1.0 / k + c / (h * k * k), da_df1 = -c / (h * k * k);
  const double db_df0 = -1.0 / (h * k), db_df1 = 1.0 / (h * k);
  // q1 = a00 (q0 - alpha) + a01 (v0 - beta) + alpha + beta h,  v1 = a10 (q0 - alpha) + a11 (v0 - beta) + beta.
  s.b0 = (1.0 - s.a00) * da_df0 + (h - s.a01) * db_df0;
  s.b1 = (1.0 - s.a00) * da_df1 + (h - s.a01) * db_df1;
  s.c0 = -s.a10 * da_df0 + (1.0 - s.a11) * db_df0;
  s.c1 = -s.a10 * da_df1 + (1.0 - s.a11) * db_df1;
  return s;
}

}  // namespace rollspec::integrators
