// IEC 61260-1 base-ten third-octave bands.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "kernels/spectral/third_octave_bands.hpp"

using namespace rollspec::spectral;

TEST_CASE("band centres and edges follow IEC 61260-1 base-ten (G = 10^(3/10))") {
  const Band b0 = third_octave_band(0);
  CHECK(b0.centre == doctest::Approx(1000.0).epsilon(1e-15));
  CHECK(b0.lower == doctest::Approx(1000.0 * std::pow(10.0, -0.05)).epsilon(1e-15));
  CHECK(b0.upper == doctest::Approx(1000.0 * std::pow(10.0, 0.05)).epsilon(1e-15));
  // Exact midband frequencies from IEC 61260-1 Table E.1 (base ten), to the digits it prints.
  const struct {
    int x;
    double exact;
    double nominal;
  } table[] = {
      {-20, 10.0, 10.0},   {-10, 100.0, 100.0}, {-9, 125.89, 125.0}, {-1, 794.33, 800.0},    {1, 1258.9, 1250.0},
      {5, 3162.3, 3150.0}, {7, 5011.9, 5000.0}, {8, 6309.6, 6300.0}, {13, 19953.0, 20000.0}, {-17, 19.953, 20.0},
  };
  for (const auto& t : table) {
    const Band b = third_octave_band(t.x);
    CHECK(b.centre == doctest::Approx(t.exact).epsilon(5e-5));
    CHECK(b.nominal == doctest::Approx(t.nominal).epsilon(1e-12));
    CHECK(b.upper / b.lower == doctest::Approx(std::pow(10.0, 0.1)).epsilon(1e-14));
  }
  // Adjacent bands share their edges.
  CHECK(third_octave_band(3).upper == doctest::Approx(third_octave_band(4).lower).epsilon(1e-14));
}

TEST_CASE("third_octave_bands lists exactly the bands inside the range") {
  const auto bands = third_octave_bands(third_octave_band(-10).lower, third_octave_band(7).upper);
  REQUIRE(bands.size() == 18);
  CHECK(bands.front().nominal == 100.0);
  CHECK(bands.back().nominal == 5000.0);
}

TEST_CASE("band averages of a flat PSD are the PSD, of a linear PSD the midpoint value") {
  const double df = 0.5;
  std::vector<double> flat(4001, 3.0), linear(4001);
  for (std::size_t k = 0; k < linear.size(); ++k) linear[k] = 2.0 * df * static_cast<double>(k);
  const Band b = third_octave_band(-10);  // 100 Hz
  CHECK(band_average(flat.data(), flat.size(), df, b.lower, b.upper) == doctest::Approx(3.0).epsilon(1e-14));
  // Bins are densities over [f_k - df/2, f_k + df/2]: with edges on bin boundaries the average is exact.
  CHECK(band_average(linear.data(), linear.size(), df, 99.75, 120.25) ==
        doctest::Approx(99.75 + 120.25).epsilon(1e-13));
  std::vector<double> f(linear.size());
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = df * static_cast<double>(k);
  CHECK(band_average_irregular(f.data(), linear.data(), f.size(), b.lower, b.upper) ==
        doctest::Approx(b.lower + b.upper).epsilon(1e-12));
  CHECK(std::isnan(band_average_irregular(f.data(), linear.data(), f.size(), 1900.0, 2100.0)));
}

TEST_CASE("band_rule_shift: the two band rules agree on a flat PSD and part beside a spike") {
  const std::vector<double> flat(12, 3.0);
  CHECK(band_rule_shift(flat.data(), flat.size(), 1.0, 3.6, 4.4) == doctest::Approx(0.0).epsilon(1e-15));
  // A spike of 101 in bin 3, 1 elsewhere; the band [3.6, 4.4] lies inside bin 4 ([3.5, 4.5]): the bin
  // rule reads 1. Linearly, 41 at 3.6 falls to 1 at 4: (0.4 (41 + 1) / 2 + 0.4) / 0.8 = 11.
  std::vector<double> spike(12, 1.0);
  spike[3] = 101.0;
  CHECK(band_rule_shift(spike.data(), spike.size(), 1.0, 3.6, 4.4) == doctest::Approx(std::log(11.0)).epsilon(1e-13));
  // Wide bands see the spike by both rules nearly alike.
  std::vector<double> wide(400, 1.0);
  wide[100] = 101.0;
  CHECK(std::fabs(band_rule_shift(wide.data(), wide.size(), 1.0, 50.0, 250.0)) < 1e-9);
}
