// Hertz's closed forms (kernels/contact/hertz.hpp) against Johnson, Contact Mechanics (1985) §4.2: the
// module writes each quantity once, in one form; these checks use Johnson's other forms of the same
// quantities, a case worked by hand, and the seed ball's numbers (kernels/README.md (contact)).
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/contact/hertz.hpp"

using namespace rollspec::contact;

TEST_CASE("Hertz closed forms: a case worked by hand") {
  // R = 1 m, E* = 3 GPa, P = 4 N: a³ = 3·4·1 / (4·3e9) = 1e-9, so a = 1 mm, δ = a²/R = 1 µm,
  // p0 = 3P / (2π a²) = 6/π MPa, k = 2 E* a = 6e6 N/m, K = (4/3) E* sqrt(R) = 4e9 N/m^1.5.
  const double r = 1.0, e = 3e9, p = 4.0;
  CHECK(hertz::contact_radius_at_load(r, e, p) == doctest::Approx(1e-3).epsilon(1e-15));
  CHECK(hertz::approach_at_load(r, e, p) == doctest::Approx(1e-6).epsilon(1e-15));
  CHECK(hertz::force_coefficient(r, e) == doctest::Approx(4e9).epsilon(1e-15));
  CHECK(hertz::force_at_approach(r, e, 1e-6) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(hertz::contact_radius_at_approach(r, 1e-6) == doctest::Approx(1e-3).epsilon(1e-15));
  CHECK(hertz::stiffness_at_approach(r, e, 1e-6) == doctest::Approx(6e6).epsilon(1e-15));
  CHECK(hertz::peak_pressure_at_load(r, e, p) == doctest::Approx(6e6 / M_PI).epsilon(1e-15));
  CHECK(hertz::peak_pressure_at_approach(r, e, 1e-6) == doctest::Approx(6e6 / M_PI).epsilon(1e-15));
}

TEST_CASE("Hertz closed forms: Johnson's other forms (4.22)-(4.24) over radii, moduli and loads") {
  for (double r : {1e-3, 0.02, 0.5})
    for (double e : {1e6, 115.4e9})
      for (double p : {1e-3, 2.58, 1e4}) {
        CAPTURE(r);
        CAPTURE(e);
        CAPTURE(p);
        const double a = hertz::contact_radius_at_load(r, e, p), d = hertz::approach_at_load(r, e, p);
        CHECK(d == doctest::Approx(std::cbrt(9.0 * p * p / (16.0 * r * e * e))).epsilon(1e-14));  // (4.23)
        CHECK(d == doctest::Approx(a * a / r).epsilon(1e-14));                                    // (4.23)
        CHECK(hertz::peak_pressure_at_load(r, e, p) ==
              doctest::Approx(std::cbrt(6.0 * p * e * e / (M_PI * M_PI * M_PI * r * r))).epsilon(1e-14));  // (4.24)
        // The mean pressure is 2/3 of the peak (Johnson 4.24).
        CHECK(p / (M_PI * a * a) == doctest::Approx(2.0 / 3.0 * hertz::peak_pressure_at_load(r, e, p)).epsilon(1e-14));
        // Forward and back: the force at δ(P) is P, the radius at δ(P) is a(P).
        CHECK(hertz::force_at_approach(r, e, d) == doctest::Approx(p).epsilon(1e-14));
        CHECK(hertz::contact_radius_at_approach(r, d) == doctest::Approx(a).epsilon(1e-14));
        CHECK(hertz::peak_pressure_at_approach(r, e, d) ==
              doctest::Approx(hertz::peak_pressure_at_load(r, e, p)).epsilon(1e-14));
        // k = dP/dδ, against a central difference of P(δ) (truncation ~ (h/δ)² / 8).
        const double h = 1e-5 * d;
        const double fd = (hertz::force_at_approach(r, e, d + h) - hertz::force_at_approach(r, e, d - h)) / (2.0 * h);
        CHECK(hertz::stiffness_at_approach(r, e, d) == doctest::Approx(fd).epsilon(1e-8));
      }
}

TEST_CASE("Hertz closed forms: the seed ball under its own weight, and no contact") {
  // 40 mm steel ball on steel, E* = 115.4 GPa, 2.58 N: δ = 0.241 µm, a = 69 µm, k = 1.60e7 N/m.
  const double r = 0.02, e = 115.4e9, w = 2.58;
  CHECK(hertz::approach_at_load(r, e, w) == doctest::Approx(0.241e-6).epsilon(2e-3));
  CHECK(hertz::contact_radius_at_load(r, e, w) == doctest::Approx(69.5e-6).epsilon(2e-3));
  CHECK(hertz::stiffness_at_approach(r, e, hertz::approach_at_load(r, e, w)) == doctest::Approx(1.60e7).epsilon(3e-3));
  for (double d : {0.0, -1e-6}) {
    CHECK(hertz::force_at_approach(r, e, d) == 0.0);
    CHECK(hertz::contact_radius_at_approach(r, d) == 0.0);
  }
  CHECK(hertz::approach_at_load(r, e, 0.0) == 0.0);
  CHECK(hertz::contact_radius_at_load(r, e, 0.0) == 0.0);
}
