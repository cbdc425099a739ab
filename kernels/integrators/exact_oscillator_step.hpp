#pragma once
// Exact one-step propagator of a unit-mass linear oscillator (theory D-18)
//
//   q'' + 2 zeta omega q' + omega^2 q = f(t),   f linear over the step: f(t) = f0 + (f1 - f0) t / h,
//
// written as the 2x2 affine map
//   q1 = a00 q0 + a01 v0 + b0 f0 + b1 f1
//   v1 = a10 q0 + a11 v0 + c0 f0 + c1 f1
// (first-order-hold discretisation). The coefficients are exact: they come from the matrix
// exponential of the augmented system z = [q, v, f, f'] (Van Loan 1978),
//   z' = M z,  M = [[0, 1, 0, 0], [-w^2, -2 zeta w, 1, 0], [0, 0, 0, 1], [0, 0, 0, 0]],
// computed once per (omega, zeta, h) by Eigen's Pade scaling-and-squaring exponential, which
// stays accurate for omega = 0 (rigid-body mode), for critical damping and for omega h >> 1.
// A step then costs eight multiply-adds, so a modal model with hundreds of modes steps in
// microseconds.
namespace rollspec::integrators {

struct ExactOscillatorStep {
  double a00, a01, a10, a11;  // free response over h
  double b0, b1, c0, c1;      // response to the end-point forces of the linear ramp

  static ExactOscillatorStep make(double omega, double zeta, double h);

  void advance(double& q, double& v, double f0, double f1) const {
    const double q1 = a00 * q + a01 * v + b0 * f0 + b1 * f1;
    const double v1 = a10 * q + a11 * v + c0 * f0 + c1 * f1;
    q = q1;
    v = v1;
  }
};

// Closed-form propagator for 0 <= zeta < 1, omega > 0 (Nigam & Jennings 1969): the reference
// oracle that tests compare make() with.
ExactOscillatorStep exact_oscillator_step_closed_form(double omega, double zeta, double h);

}  // namespace rollspec::integrators
