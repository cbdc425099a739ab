// The one number formatter (io/number_text.hpp) prints as printf's %.*g, so every message, plan and
// table text the named forms make reads as before they shared it.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "src/io/number_text.hpp"

using namespace rollspec;

TEST_CASE("number text: significant digits as %g, the named forms, SI prefixes") {
  CHECK(io::significant_text(0.05, 17) == "0.050000000000000003");
  CHECK(io::exact_text(0.05) == "0.050000000000000003");
  CHECK(io::significant_text(1234.5, 10) == "1234.5");
  CHECK(io::number_text(1234567.0) == "1.23457e+06");
  CHECK(io::four_digits(0.000123456) == "0.0001235");
  CHECK(io::three_digits(2.0 / 3.0) == "0.667");
  CHECK(io::number_text(-INFINITY) == "-inf");
  CHECK(io::number_text(NAN) == "nan");
  CHECK(io::si_text(1.5625e-7, "m") == "156.25 nm");
  CHECK(io::length_text(2.0) == "2 m");
  CHECK(io::si_text(0.0086722, "m", 3) == "8.67 mm");
}
