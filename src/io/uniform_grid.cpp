#include "src/io/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

double PrintedDigits::printed_half_unit(double v) const {
  const double fixed = decimals >= 400 ? 0.0 : std::pow(10.0, -decimals);
  const double sig =
      v == 0.0 || significant >= 400 ? 0.0 : std::pow(10.0, std::floor(std::log10(std::fabs(v))) - significant + 1);
  return 0.5 * std::max(fixed, sig);
}

double PrintedDigits::half_unit(double v) const {
  // plus what the decimal text loses in binary: a few units in the last place of v
  return printed_half_unit(v) + 4 * std::numeric_limits<double>::epsilon() * std::fabs(v);
}

double uniform_grid_step(const std::vector<double>& v, const std::function<std::string(std::size_t)>& where,
                         const GridNames& g, const PrintedDigits& digits, bool* fitted) {
  const std::size_t n = v.size();
  if (n < 2) throw std::logic_error("uniform_grid_step needs at least 2 values");
  const double d = (v[n - 1] - v[0]) / static_cast<double>(n - 1);
  const auto rounding = [&](std::size_t i) { return digits.half_unit(v[i]); };
  const std::string allowed =
      "; allowed: " + g.allowed + (digits.exact() ? "" : ", or within the rounding of its printed digits");
  const std::string ends = " from the first and last " + g.values + ")";
  for (std::size_t i = 1; i < n; ++i)
    if (!(v[i] > v[i - 1]) && !(d > 0.0 && d - (v[i] - v[i - 1]) <= rounding(i) + rounding(i - 1)))
      throw data_error(where(i) + ": " + g.column + " value " + g.text(v[i]) + " does not increase (" + g.previous +
                       " " + g.text(v[i - 1]) + ")" + allowed);
  // Steps first: a gap or a repeated sample is named at its own line, not where the drift it causes
  // first shows on the grid.
  for (std::size_t i = 1; i < n; ++i) {
    const double step = v[i] - v[i - 1];
    if (std::fabs(step - d) > std::max(0.5 * d, rounding(i) + rounding(i - 1)))
      throw data_error(where(i) + ": " + g.column + " steps by " + g.text(step) + " (from " + g.text(v[i - 1]) +
                       " to " + g.text(v[i]) + "), " + number_text(step / d) + " " + g.interval + "s of the " +
                       g.record + " (" + g.step + " = " + g.text(d) + ends + ": a missing, repeated or shifted sample" +
                       allowed);
  }
  const double end_rounding = std::max(rounding(0), rounding(n - 1));
  for (std::size_t i = 1; i < n; ++i) {
    const double off = (v[i] - v[0]) - static_cast<double>(i) * d;
    const double tolerance = std::max(kGridTolerance * d, rounding(i) + end_rounding);
    if (std::fabs(off) > tolerance)
      throw data_error(where(i) + ": " + g.column + " value " + g.text(v[i]) + " is " + number_text(off / d) + " " +
                       g.interval + "s off the uniform grid " + g.grid + " (by " + g.text(off) + "; " + g.step + " = " +
                       g.text(d) + ends + ", more than the " + number_text(tolerance / d) +
                       " allowed here: " + g.uneven + allowed);
  }
  // Values rounded to a few digits: the first and last carry that rounding into the step whole (2 ppm
  // at six digits over 2.5 s); a least-squares line through all of them averages it out. Exact values
  // keep the end-point step, which for i/fs on binary fractions is exactly 1/fs.
  const bool fit = std::max(digits.printed_half_unit(v[0]), digits.printed_half_unit(v[n - 1])) > 1e-9 * d;
  if (fitted) *fitted = fit;
  if (!fit) return d;
  long double mean_v = 0.0L;
  for (const double x : v) mean_v += x;
  mean_v /= static_cast<long double>(n);
  const long double mean_i = static_cast<long double>(n - 1) / 2.0L;
  long double sxy = 0.0L, sxx = 0.0L;
  for (std::size_t i = 0; i < n; ++i) {
    const long double di = static_cast<long double>(i) - mean_i;
    sxy += di * (static_cast<long double>(v[i]) - mean_v);
    sxx += di * di;
  }
  return static_cast<double>(sxy / sxx);
}

}  // namespace rollspec::io
