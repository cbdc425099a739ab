// Chi-square interval of an averaged PSD.
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/spectral/confidence.hpp"

using namespace rollspec::spectral;

TEST_CASE("25 averaged periodograms give -1.55 / +1.89 dB at 95 % (kernels/README.md (spectra))") {
  const auto f = chi_square_interval(50.0, 0.95);
  CHECK(10.0 * std::log10(f.lower) == doctest::Approx(-1.55).epsilon(0.005));
  CHECK(10.0 * std::log10(f.upper) == doctest::Approx(1.89).epsilon(0.005));
  // chi2_{0.975}(2) = 7.3778, chi2_{0.025}(2) = 0.050636 (tables).
  const auto g = chi_square_interval(2.0, 0.95);
  CHECK(g.lower == doctest::Approx(2.0 / 7.37776).epsilon(1e-5));
  CHECK(g.upper == doctest::Approx(2.0 / 0.0506356).epsilon(1e-5));
  CHECK_THROWS(chi_square_interval(0.0));
}
