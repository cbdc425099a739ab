#pragma once
// Exact one-step propagator of a unit-mass oscillator for a force that is QUADRATIC over the step
// (second-order hold through three consecutive step values), README Eq. (B36):
//   q'' + 2 zeta w q' + w^2 q = f(tau),  f the parabola through (-h, f_m), (0, f_0), (h, f_1),
//   q1 = a00 q0 + a01 v0 + bm f_m + b0 f_0 + b1 f_1,   v1 = a10 q0 + a11 v0 + cm f_m + c0 f_0 + c1 f_1.
// Coefficients from the exponential of the augmented system z = [q, v, f, f', f''] (Van Loan 1978):
// with E = exp(M h), f(0) = f_0, f'(0) = (f_1 - f_m)/(2h), f''(0) = (f_1 - 2 f_0 + f_m)/h^2.
// When the three values lie on a line it equals the first-order hold (ExactOscillatorStep).
namespace rollspec::beam {

struct QuadraticHoldStep {
  double a00, a01, a10, a11;
  double bm, b0, b1;
  double cm, c0, c1;

  static QuadraticHoldStep make(double omega, double zeta, double h);
};

}  // namespace rollspec::beam
