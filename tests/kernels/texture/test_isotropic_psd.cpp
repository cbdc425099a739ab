// The Abel pair of D-5: C_iso from the line PSD (Eq. 19) and back (Eq. 18).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "kernels/texture/isotropic_psd.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;

TEST_CASE("inverse Abel of a pure power law matches the closed form") {
  // G = A q^-a  =>  C_iso(r) = 2 pi a A r^{-a-1} (sqrt(pi)/2) Gamma((a+1)/2) / Gamma(a/2 + 1).
  const double A = 1e-12, a = 2.6;
  Psd g;
  g.density = [=](double q) { return A * std::pow(q, -a); };
  g.description = "power law";
  const IsotropicPsd iso(g, 1.0, 1e7, 100);  // truncated at 1e7: (r / 1e7)^{a+1} is negligible below 1e4
  double worst = 0.0;
  for (double r : {2.0, 10.0, 55.0, 300.0, 1e3, 4e3}) {
    const double exact = 2.0 * M_PI * a * A * std::pow(r, -a - 1.0) * 0.5 * std::sqrt(M_PI) *
                         std::tgamma(0.5 * (a + 1.0)) / std::tgamma(0.5 * a + 1.0);
    worst = std::max(worst, std::abs(iso(r) / exact - 1.0));
  }
  MESSAGE("power law: max relative error of Eq. 19 = " << worst);
  CHECK(worst <= 1e-6);
}

TEST_CASE("Abel pair: the forward integral of C_iso returns the line PSD") {
  // Self-affine with plateau, kink at k_r and a hard cut-off at k_s (the jump term of Eq. 20).
  const auto& [model, g, iso] = texture_test::AbelPair{};
  CHECK(iso.end_jump() == doctest::Approx(model(1e5)));
  CHECK(iso.clamped_fraction() == 0.0);
  double worst = 0.0, worst_q = 0.0;
  for (double q = 20.0; q < 0.97e5; q *= 1.07) {
    const double back = iso.forward_line_psd(q, 4000);
    const double e = std::abs(back / model(q) - 1.0);
    if (e > worst) {
      worst = e;
      worst_q = q;
    }
  }
  MESSAGE("Abel pair: max relative error " << worst << " at q = " << worst_q << " rad/m (q in [20, 0.97 k_s])");
  CHECK(worst <= 1e-3);  // 0.004 dB: the log-grid representation of C_iso at 200 points per decade
}

TEST_CASE("a hard long-wavelength cut-off is not an isotropic projection: negative C_iso is clamped and reported") {
  const SelfAffinePsd model(SelfAffineSpec{0.8, 500.0, 2e3, 1e5, RmsTarget::height, 1e-6});
  const IsotropicPsd iso(model.to_psd(), 10.0, 1e9, 100);
  CHECK(iso.clamped_fraction() > 0.0);
  CHECK(iso(100.0) >= 0.0);
}
