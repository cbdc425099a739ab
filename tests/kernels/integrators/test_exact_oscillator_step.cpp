// Exact first-order-hold oscillator step (D-18).
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "kernels/integrators/exact_oscillator_step.hpp"

using namespace rollspec::integrators;

TEST_CASE("matrix-exponential coefficients equal the closed form (Nigam-Jennings)") {
  for (double zeta : {0.0, 0.01, 0.3, 0.9}) {
    for (double wh : {1e-3, 0.1, 1.0, 3.0}) {
      const double omega = 2.0 * M_PI * 37.0, h = wh / omega;
      const auto a = ExactOscillatorStep::make(omega, zeta, h);
      const auto b = exact_oscillator_step_closed_form(omega, zeta, h);
      // Relative to the natural size of each coefficient.
      CHECK(a.a00 == doctest::Approx(b.a00).epsilon(1e-11));
      CHECK(a.a01 * omega == doctest::Approx(b.a01 * omega).epsilon(1e-11));
      CHECK(a.a10 / omega == doctest::Approx(b.a10 / omega).epsilon(1e-11));
      CHECK(a.a11 == doctest::Approx(b.a11).epsilon(1e-11));
      const double fscale = omega * omega;  // force -> displacement
      CHECK(a.b0 * fscale == doctest::Approx(b.b0 * fscale).epsilon(wh < 0.01 ? 1e-6 : 1e-10));
      CHECK(a.b1 * fscale == doctest::Approx(b.b1 * fscale).epsilon(wh < 0.01 ? 1e-6 : 1e-10));
      CHECK(a.c0 * omega == doctest::Approx(b.c0 * omega).epsilon(wh < 0.01 ? 1e-6 : 1e-10));
      CHECK(a.c1 * omega == doctest::Approx(b.c1 * omega).epsilon(wh < 0.01 ? 1e-6 : 1e-10));
    }
  }
}

TEST_CASE("a ramp force is followed exactly, with no time-step error") {
  // q'' + w^2 q = r t from rest: q = r/w^2 (t - sin(w t)/w).
  const double w = 10.0, r = 3.0, h = 0.37;  // w h = 3.7: far beyond any explicit stability limit
  const auto s = ExactOscillatorStep::make(w, 0.0, h);
  double q = 0.0, v = 0.0;
  for (int i = 0; i < 50; ++i) s.advance(q, v, r * i * h, r * (i + 1) * h);
  const double t = 50 * h;
  CHECK(q == doctest::Approx(r / (w * w) * (t - std::sin(w * t) / w)).epsilon(1e-12));
  CHECK(v == doctest::Approx(r / (w * w) * (1.0 - std::cos(w * t))).epsilon(1e-11));
}

TEST_CASE("rigid-body mode (omega = 0) integrates a linear force exactly") {
  const auto s = ExactOscillatorStep::make(0.0, 0.0, 0.5);
  double q = 1.0, v = 2.0;
  s.advance(q, v, 4.0, 6.0);  // a(t) = 4 + 4 t on [0, 0.5]
  CHECK(v == doctest::Approx(2.0 + 4.0 * 0.5 + 2.0 * 0.25).epsilon(1e-14));
  CHECK(q == doctest::Approx(1.0 + 2.0 * 0.5 + 2.0 * 0.25 + 4.0 / 6.0 * 0.125).epsilon(1e-14));
  CHECK_THROWS(ExactOscillatorStep::make(1.0, 0.0, 0.0));
}
