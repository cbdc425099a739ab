// One rule for values that should lie on a uniform grid as a file printed them (src/io/uniform_grid):
// measured profiles' positions and measured signals' time stamps.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/time_column.hpp"
#include "src/io/uniform_grid.hpp"
#include "src/texture/profile_source.hpp"

using namespace rollspec;

namespace {
// The profile reader's own names (its messages are what the grid rule is checked by).
io::GridNames position_names() { return texture_io::profile_position_names(); }

// 9600 positions of 0.15625 um printed to 0.1 um (a Dektak export): 7 decimals in metres.
std::vector<double> dektak_positions(double shift_from = 1e9, std::size_t at = 0) {
  std::vector<double> x(9600);
  for (std::size_t i = 0; i < x.size(); ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7f", static_cast<double>(i) * 0.15625e-6 + (i >= at ? shift_from : 0.0));
    x[i] = std::strtod(text, nullptr);
  }
  return x;
}

std::string where(std::size_t i) { return "scan.csv:" + std::to_string(i + 2); }
}  // namespace

TEST_CASE("uniform grid: positions rounded to their printed digits give the step they were printed from") {
  const auto x = dektak_positions(0.0);
  bool fitted = false;
  const double dx = io::uniform_grid_step(x, where, position_names(), io::PrintedDigits{7, 6}, &fitted);
  CHECK(fitted);
  CHECK(std::abs(dx / 0.15625e-6 - 1.0) < 1e-6);  // the least-squares slope; the end points alone: 3.5e-5 off
  CHECK(std::abs((x.back() - x.front()) / 9599.0 / 0.15625e-6 - 1.0) > 1e-5);
  // The same positions taken as exact (no printed digits) are off the grid by up to 0.32 steps: refused.
  CHECK_THROWS_AS(io::uniform_grid_step(x, where, position_names()), UserError);
}

TEST_CASE("uniform grid: exact values keep the end-point step; a gap is named at its line, lengths in SI") {
  std::vector<double> x(100);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.5e-6 * static_cast<double>(i);
  bool fitted = true;
  CHECK(io::uniform_grid_step(x, where, position_names(), {}, &fitted) == (x.back() - x.front()) / 99.0);
  CHECK_FALSE(fitted);
  const auto gap = dektak_positions(0.2e-6, 700);
  try {
    io::uniform_grid_step(gap, where, position_names(), io::PrintedDigits{7, 6});
    FAIL("a 0.2 um gap must be refused");
  } catch (const UserError& e) {
    CHECK(e.exit_code() == EX_DATAERR);
    CHECK(std::string(e.what()).rfind("scan.csv:702: column 'position_m' steps by 400 nm (from 109.2 um to 109.6 um)",
                                      0) == 0);
  }
}

TEST_CASE("uniform grid: time stamps printed to six significant digits give their rate (the shared rule)") {
  std::vector<double> t(64000);
  for (std::size_t i = 0; i < t.size(); ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", static_cast<double>(i) / 25600.0);
    t[i] = std::strtod(text, nullptr);
  }
  const double fs = io::rate_from_time_stamps(t, 1.0, "time_s", where, io::PrintedDigits{10, 6});
  CHECK(std::abs(fs / 25600.0 - 1.0) < 1e-6);
}
