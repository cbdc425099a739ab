// The iso2d contact filter (README §11, Eq. 36-40): the flat-punch weight's transform, its 1D
// limit (the patch filter B35), the a -> 0 limit (Eq. 18) and closed forms of Eq. 38.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/texture/contact_filtered_psd.hpp"
#include "kernels/texture/isotropic_psd.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;

namespace {

// Si(x) by its power series in long double (exact to ~1e-12 relative for x <= 20).
double sine_integral(double x) {
  long double term = x, sum = x;
  const long double x2 = static_cast<long double>(x) * x;
  for (int n = 1; n < 200; ++n) {
    term *= -x2 / ((2.0L * n) * (2.0L * n + 1.0L));
    sum += term / (2.0L * n + 1.0L);
  }
  return static_cast<double>(sum);
}

// int_0^X sin^2(u)/u du = (1/2) sum_{n>=1} (-1)^{n+1} (2X)^{2n} / (2n (2n)!)
double sin2_over_u(double x) {
  long double term = 1.0L, sum = 0.0L;
  const long double z2 = 4.0L * x * x;
  for (int n = 1; n < 200; ++n) {
    term *= z2 / ((2.0L * n - 1.0L) * (2.0L * n));  // (2X)^{2n} / (2n)!
    sum += (n % 2 ? 1.0L : -1.0L) * term / (2.0L * n);
  }
  return static_cast<double>(0.5L * sum);
}

IsotropicSpectrum white(double c0, double q_end) {
  IsotropicSpectrum c;
  c.smooth = [c0](double) { return c0; };
  c.q_end = q_end;
  return c;
}

}  // namespace

TEST_CASE("flat-punch weight: its 2D Fourier transform is sin(qa)/(qa) (Eq. 37)") {
  // w^(q) = int_0^a 2 pi r J0(q r) w(r) dr = int_0^{pi/2} sin(phi) J0(q a sin(phi)) dphi  (r = a sin phi)
  double worst = 0.0;
  for (double s : {0.0, 0.3, 1.0, 2.5, M_PI, 4.7, 9.0, 17.0}) {
    const int n = 4000;
    const double h = 0.5 * M_PI / n;
    double acc = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double phi = h * i, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      acc += w * std::sin(phi) * std::cyl_bessel_j(0.0, s * std::sin(phi));
    }
    acc *= h / 3.0;
    worst = std::max(worst, std::abs(acc - flat_punch_transfer(s)));
  }
  MESSAGE("Hankel transform of the flat-punch weight vs sin(s)/s: max abs error " << worst);
  CHECK(worst <= 1e-10);
}

TEST_CASE("uniform corrugation: the 2D weight at (k, 0) is the 1D patch filter B35") {
  // contact_patch_transfer is B35a on samples: sin(ka)/(ka) sinc^2(k dx/2) + O(dx/a).
  const double a = 69e-6, dx = a / 2000.0;
  double worst = 0.0;
  for (double ka : {0.1, 0.5, 1.0, 2.0, M_PI, 5.0, 10.0, 20.0}) {
    const double k = ka / a, interp = std::pow(std::sin(0.5 * k * dx) / (0.5 * k * dx), 2);
    worst =
        std::max(worst, std::abs(rollspec::beam::contact_patch_transfer(k, a, dx) / interp - flat_punch_transfer(ka)));
  }
  MESSAGE("B35a / sinc^2(k dx/2) vs sin(ka)/(ka) at dx = a/2000: max abs difference " << worst);
  CHECK(worst <= 1e-3);
}

TEST_CASE("a -> 0: Eq. 38 is the forward projection Eq. 18 and returns the line PSD") {
  const auto& [model, g, iso] = texture_test::AbelPair{};
  const IsotropicSpectrum c = isotropic_spectrum(iso, g.breakpoints);
  double worst_forward = 0.0, worst_line = 0.0;
  for (double k = 20.0; k < 0.97e5; k *= 1.13) {
    const double geq = contact_filtered_line_psd(c, 0.0, k);
    worst_forward = std::max(worst_forward, std::abs(geq / iso.forward_line_psd(k, 20000) - 1.0));
    worst_line = std::max(worst_line, std::abs(geq / model(k) - 1.0));
  }
  MESSAGE("a = 0: max relative difference to Eq. 18 (Simpson) " << worst_forward << ", to G(k) " << worst_line);
  CHECK(worst_forward <= 1e-4);
  CHECK(worst_line <= 1e-3);  // the Abel pair's own accuracy at 200 points per decade (test_isotropic_psd)
  // A contact much smaller than the shortest wavelength changes nothing either.
  CHECK(contact_filtered_line_psd(c, 1e-9, 3e4) ==
        doctest::Approx(contact_filtered_line_psd(c, 0.0, 3e4)).epsilon(1e-6));
}

TEST_CASE("closed forms of Eq. 38 for a white isotropic spectrum") {
  const double c0 = 2.5e-20, q_end = 1e5;
  const IsotropicSpectrum c = white(c0, q_end);
  for (double a : {1e-5, 5e-5, 1e-4}) {
    // k = 0: pi^-2 C0 int_0^{q_e} sin^2(a y)/(a y)^2 dy = C0 / (pi^2 a) [Si(2 a q_e) - sin^2(a q_e)/(a q_e)]
    const double x = a * q_end;
    const double exact = c0 / (M_PI * M_PI * a) * (sine_integral(2.0 * x) - std::sin(x) * std::sin(x) / x);
    CHECK(contact_filtered_line_psd(c, a, 0.0) == doctest::Approx(exact).epsilon(1e-9));
  }
  // Parseval: int_0^inf G_eq dk = (2 pi)^-2 int C W d^2q = C0 / (2 pi a^2) int_0^{a q_e} sin^2(u)/u du.
  const double a = 5e-5;
  const int n = 20000;
  const double h = q_end / n;
  double total = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    total += w * contact_filtered_line_psd(c, a, h * i);
  }
  total *= h / 3.0;
  const double exact = c0 / (2.0 * M_PI * a * a) * sin2_over_u(a * q_end);
  MESSAGE("white spectrum: variance along the path " << total << " vs exact " << exact);
  CHECK(total == doctest::Approx(exact).epsilon(1e-4));  // Simpson in k over G_eq's sqrt edge at q_e
}

TEST_CASE("Eq. 39 (Gauss panels) against the plain trapezoid reference of Eq. 38") {
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 2e3, 1e5, RmsTarget::height, 1e-6});
  const Psd g = model.to_psd();
  const IsotropicPsd iso(g, 10.0, 1e9, 100);
  const IsotropicSpectrum c = isotropic_spectrum(iso, g.breakpoints);
  double worst = 0.0;
  for (double a : {2e-5, 1e-4, 7e-4}) {
    for (double k : {50.0, 500.0, 2e3, 5e3, 2e4, 6e4, 9.9e4}) {
      const double fast = contact_filtered_line_psd(c, a, k),
                   ref = contact_filtered_line_psd_reference(c, a, k, 1000000);
      worst = std::max(worst, std::abs(fast / ref - 1.0));
      CHECK(fast <= model(k) * (1.0 + 1e-3));  // W <= 1: the filter only removes power
    }
  }
  MESSAGE("Eq. 39 vs trapezoid reference (1e6 intervals): max relative difference " << worst);
  // S is log-log between IsotropicPsd's nodes (kinks every 1/100 decade, inside the Gauss panels):
  // ~3e-5, well inside the Abel pair's own 1e-3 (test above). The reference is converged to 5e-8.
  CHECK(worst <= 1e-4);
}

TEST_CASE("the tabulated G_eq the engine synthesises from") {
  const SelfAffinePsd model(SelfAffineSpec{0.8, 0.0, 1.26e5, 1.57e6, RmsTarget::height, 0.36e-6});
  const Psd g = model.to_psd();
  const double a = 69e-6;
  const Psd geq = contact_filtered_psd(g, a, 5.0, 1e9, 4e5, 200);
  const IsotropicPsd iso(g, 2.5, 1e9, 100);
  const IsotropicSpectrum c = isotropic_spectrum(iso, g.breakpoints);
  double worst = 0.0;
  for (double k = 7.3; k < 3.2e5; k *= 1.0371)
    worst = std::max(worst, std::abs(geq(k) / contact_filtered_line_psd(c, a, k) - 1.0));
  MESSAGE(
      "log-log table of G_eq (200 per decade, steps <= pi/64a) vs Eq. 39 between nodes, k < 3.2e5 rad/m: " << worst);
  CHECK(worst <= 2e-3);
  // ka << 1: the contact sees the line PSD; ka >> 1: far less (2D averaging).
  CHECK(geq(100.0) == doctest::Approx(model(100.0)).epsilon(2e-3));
  CHECK(geq(2e5) < 0.1 * model(2e5));
  CHECK(geq(5e5) == 0.0);  // beyond k_max: nobody asks
  CHECK_THROWS_AS(contact_filtered_psd(g, 0.0, 5.0, 1e9, 4e5), std::invalid_argument);
  CHECK_THROWS_AS(contact_filtered_psd(g, a, 5.0, 1e9, 4.0), std::invalid_argument);
}
