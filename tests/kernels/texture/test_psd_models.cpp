// PSD models: table interpolation and validation, self-affine exact integrals, ISO 8608, ISO 3095.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "kernels/texture/iso3095_rail_psd.hpp"
#include "kernels/texture/iso8608_psd.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/tabulated_psd.hpp"

using namespace rollspec::texture;

namespace {
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("tabulated PSD interpolates log-log: a power law between nodes is reproduced exactly") {
  // G = 2e-9 k^-3 sampled at 3 nodes; in between, Eq. 5 must return the power law itself.
  const TabulatedPsd t({10.0, 100.0, 1000.0}, {2e-9 * 1e-3, 2e-9 * 1e-6, 2e-9 * 1e-9});
  for (double k : {10.0, 17.0, 55.5, 100.0, 420.0, 999.0})
    CHECK(t(k) == doctest::Approx(2e-9 * std::pow(k, -3.0)).epsilon(1e-12));
}

TEST_CASE("tabulated PSD outside the table: error unless an extension is given") {
  const std::vector<double> k{10.0, 20.0, 40.0}, g{1e-9, 0.25e-9, 0.125e-9};
  const TabulatedPsd none(k, g);
  CHECK_THROWS_AS(none(5.0), std::domain_error);
  CHECK_THROWS_AS(none(41.0), std::domain_error);
  CHECK(message_of([&] { none(41.0); }).find("k = 41") != std::string::npos);
  CHECK(TabulatedPsd(k, g, Extension::constant)(5.0) == 1e-9);
  CHECK(TabulatedPsd(k, g, Extension::constant)(100.0) == 0.125e-9);
  CHECK(TabulatedPsd(k, g, Extension::zero)(100.0) == 0.0);
  // Power law: first slope -2, last slope -1.
  CHECK(TabulatedPsd(k, g, Extension::power_law)(5.0) == doctest::Approx(4e-9).epsilon(1e-12));
  CHECK(TabulatedPsd(k, g, Extension::power_law)(80.0) == doctest::Approx(0.0625e-9).epsilon(1e-12));
}

TEST_CASE("tabulated PSD refuses bad tables with messages that name index and value") {
  CHECK(message_of([] { TabulatedPsd({1.0, 2.0, 3.0}, {1.0, -2.0, 1.0}); }).find("index 1 is -2") != std::string::npos);
  CHECK(message_of([] {
          TabulatedPsd({1.0, 3.0, 3.0}, {1.0, 1.0, 1.0});
        }).find("strictly increasing, but index 2") != std::string::npos);
  CHECK(message_of([] { TabulatedPsd({1.0, 3.0, 2.0}, {1.0, 1.0, 1.0}); }).find("index 2 (2)") != std::string::npos);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(message_of([&] { TabulatedPsd({1.0, 2.0}, {nan, 1.0}); }).find("value at index 0 is nan") != std::string::npos);
  CHECK(message_of([&] { TabulatedPsd({1.0, nan}, {1.0, 1.0}); }).find("abscissa at index 1") != std::string::npos);
  CHECK(message_of([] {
          TabulatedPsd({-1.0, 2.0}, {1.0, 1.0});
        }).find("abscissa at index 0 is -1") != std::string::npos);
  CHECK(message_of([] { TabulatedPsd({1.0}, {1.0}); }).find("at least 2 points") != std::string::npos);
  CHECK(message_of([] { TabulatedPsd({1.0, 2.0}, {1.0}); }).find("2 abscissae but 1 values") != std::string::npos);
  CHECK_THROWS_AS(TabulatedPsd({1.0, 2.0, 3.0}, {0.0, 1.0, 1.0}, Extension::power_law), std::invalid_argument);
  // A zero value is legal: that segment is linear.
  CHECK(TabulatedPsd({1.0, 3.0}, {0.0, 2.0})(2.0) == doctest::Approx(1.0));
}

TEST_CASE("self-affine PSD: C from the exact integrals (Eq. 7, 8) matches a fine quadrature") {
  SelfAffineSpec s{0.7, 50.0, 300.0, 3e5, RmsTarget::height, 1.5e-6};
  const SelfAffinePsd h(s);
  CHECK(h.rms_height() == doctest::Approx(1.5e-6).epsilon(1e-14));
  const Psd p = h.to_psd();
  // Quadrature in three pieces so the trapezoid never straddles the kink or the jumps.
  const double var = integrate_psd(p, 50.0, 300.0) + integrate_psd(p, 300.0, 3e5);
  CHECK(std::sqrt(var) == doctest::Approx(1.5e-6).epsilon(1e-6));
  const double slope2 = integrate_psd(p, 50.0, 300.0, 2.0) + integrate_psd(p, 300.0, 3e5, 2.0);
  CHECK(std::sqrt(slope2) == doctest::Approx(h.rms_slope()).epsilon(1e-6));

  s.target = RmsTarget::slope;
  s.rms = 0.02;
  s.hurst = 1.0;  // a = 3: the logarithmic branch of Eq. 8
  const SelfAffinePsd hs(s);
  const Psd ps = hs.to_psd();
  const double s2 = integrate_psd(ps, 50.0, 300.0, 2.0) + integrate_psd(ps, 300.0, 3e5, 2.0);
  CHECK(std::sqrt(s2) == doctest::Approx(0.02).epsilon(1e-6));
  CHECK(hs(1e6) == 0.0);
  CHECK(hs(10.0) == 0.0);
  CHECK(hs(100.0) == hs.c);
  CHECK_THROWS_AS(SelfAffinePsd(SelfAffineSpec{1.2, 0.0, 1.0, 10.0, RmsTarget::height, 1e-6}), std::invalid_argument);
  CHECK_THROWS_AS(SelfAffinePsd(SelfAffineSpec{0.8, 0.0, 10.0, 5.0, RmsTarget::height, 1e-6}), std::invalid_argument);
}

TEST_CASE("ISO 8608 classes: G_d(n0) = 16e-6 * 4^c m^3 at n0 = 0.1 cycles/m, slope -2, per rad/m by 1/(2 pi)") {
  CHECK(iso8608_reference_level('A') == doctest::Approx(16e-6));
  CHECK(iso8608_reference_level('C') == doctest::Approx(256e-6));
  CHECK(iso8608_reference_level('H') == doctest::Approx(262144e-6));
  CHECK_THROWS_AS(iso8608_reference_level('I'), std::invalid_argument);
  const Psd d = iso8608_psd(Iso8608Spec{'D', 2.0, 0.011, 2.83});
  const double k0 = wavenumber_from_spatial_frequency(0.1);
  CHECK(psd_n_from_psd_k(d(k0)) == doctest::Approx(1024e-6).epsilon(1e-12));
  CHECK(psd_n_from_psd_k(d(2.0 * k0)) == doctest::Approx(256e-6).epsilon(1e-12));
  CHECK(d(wavenumber_from_spatial_frequency(3.0)) == 0.0);
}

TEST_CASE("ISO 3095 limit: 22 bands, 17.1 dB at 0.4 m to -11 dB at 3.15 mm; band integral gives the band rms") {
  const auto bands = iso3095_rail_roughness_limit();
  REQUIRE(bands.size() == 22);
  CHECK(bands.front().level_db == 17.1);
  CHECK(bands.back().level_db == -11.0);
  // The band's exact base-ten centre lies within 3 % of 2 pi / nominal wavelength.
  for (const auto& b : bands) CHECK(std::abs(b.k_centre * b.wavelength_nominal / (2.0 * M_PI) - 1.0) < 0.03);
  // Integrating the log-log table over an interior band recovers its rms within 0.3 dB
  // (the table is a smooth curve through the band centres, not a staircase).
  const TabulatedPsd t = iso3095_rail_psd();
  const Psd p = t.to_psd();
  for (std::size_t i = 1; i + 1 < bands.size(); ++i) {
    const double var = integrate_psd(p, bands[i].k_lower, bands[i].k_upper, 0.0, 2001);
    const double level = 10.0 * std::log10(var / 1e-12);
    CHECK(std::abs(level - bands[i].level_db) < 0.3);
  }
  CHECK_THROWS_AS(t(bands.front().k_centre * 0.5), std::domain_error);
}

TEST_CASE("unit helpers: n = k / 2 pi, G_n = 2 pi G_k, G_t = G_n / v (D-2)") {
  CHECK(spatial_frequency_from_wavenumber(2.0 * M_PI * 5.0) == doctest::Approx(5.0));
  CHECK(psd_n_from_psd_k(1.0) == doctest::Approx(2.0 * M_PI));
  CHECK(psd_k_from_psd_n(psd_n_from_psd_k(3.0)) == doctest::Approx(3.0));
  CHECK(frequency_from_wavenumber(2.0 * M_PI * 100.0, 3.0) == doctest::Approx(300.0));
  CHECK(psd_time_from_psd_k(1e-12, 2.0) == doctest::Approx(2.0 * M_PI * 1e-12 / 2.0));
}
