#include "src/io/time_column.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

namespace {
std::string stamp_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

const char* const kAllowed =
    "strictly increasing, uniformly spaced stamps (each within 0.1 sample interval of t_0 + i*dt)";
}  // namespace

double time_column_unit(const std::string& name) {
  std::string n;
  for (const char c : name)
    if (!std::isspace(static_cast<unsigned char>(c)))
      n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* base : {"time", "t"}) {
    const std::string b = base;
    if (n.compare(0, b.size(), b) != 0) continue;
    const std::string unit = n.substr(b.size());
    // A bare capital T is a temperature or a tension as often as a time: only "t", "time" or a
    // name with a time unit ("T (s)") is taken for the time column.
    if (unit.empty()) return n == "t" && name.find('T') != std::string::npos ? 0.0 : 1.0;
    for (const auto& [u, seconds] : {std::pair<const char*, double>{"s", 1.0}, {"ms", 1e-3}})
      for (const auto& [open, close] :
           {std::pair<const char*, const char*>{"_", ""}, {"[", "]"}, {"(", ")"}, {"/", ""}})
        if (unit == std::string(open) + u + close) return seconds;
  }
  return 0.0;
}

double StampDigits::printed_half_unit(double t) const {
  const double fixed = decimals >= 400 ? 0.0 : std::pow(10.0, -decimals);
  const double sig =
      t == 0.0 || significant >= 400 ? 0.0 : std::pow(10.0, std::floor(std::log10(std::fabs(t))) - significant + 1);
  return 0.5 * std::max(fixed, sig);
}

double StampDigits::half_unit(double t) const {
  // plus what the decimal text loses in binary: a few units in the last place of t
  return printed_half_unit(t) + 4 * std::numeric_limits<double>::epsilon() * std::fabs(t);
}

double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const StampDigits& digits) {
  const std::size_t n = t.size();
  const std::string col = "time column '" + clip(name) + "'";
  if (n < 2)
    throw data_error(where(0) + ": " + col + " holds " + std::to_string(n) + " stamp; a sample rate needs at least 2");
  const double dt = (t[n - 1] - t[0]) / static_cast<double>(n - 1);
  const auto rounding = [&](std::size_t i) { return digits.half_unit(t[i]); };
  const std::string rounding_note = digits.decimals >= 400 ? "" : ", or within the rounding of its printed digits";
  for (std::size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1]) && !(dt > 0.0 && dt - (t[i] - t[i - 1]) <= rounding(i) + rounding(i - 1)))
      throw data_error(where(i) + ": " + col + " value " + stamp_text(t[i]) + " does not increase (previous stamp " +
                       stamp_text(t[i - 1]) + "); allowed: " + kAllowed + rounding_note);
  // Steps first: a gap or a repeated sample is named at its own line, not where the drift it causes
  // first shows on the grid.
  for (std::size_t i = 1; i < n; ++i) {
    const double step = t[i] - t[i - 1];
    if (std::fabs(step - dt) > std::max(0.5 * dt, rounding(i) + rounding(i - 1)))
      throw data_error(where(i) + ": " + col + " steps by " + stamp_text(step) + " (from " + stamp_text(t[i - 1]) +
                       " to " + stamp_text(t[i]) + "), " + number_text(step / dt) +
                       " sample intervals of the record (dt = " + stamp_text(dt) +
                       " from the first and last stamps): a missing, repeated or shifted sample; allowed: " + kAllowed +
                       rounding_note);
  }
  const double ends = std::max(rounding(0), rounding(n - 1));
  for (std::size_t i = 1; i < n; ++i) {
    const double off = (t[i] - t[0]) - static_cast<double>(i) * dt;
    const double allowed = std::max(kTimeGridTolerance * dt, rounding(i) + ends);
    if (std::fabs(off) > allowed)
      throw data_error(where(i) + ": " + col + " value " + stamp_text(t[i]) + " is " + number_text(off / dt) +
                       " sample intervals off the uniform grid t_0 + i*dt (by " + stamp_text(off) + "; dt = " +
                       stamp_text(dt) + " from the first and last stamps), more than the " + number_text(allowed / dt) +
                       " allowed here: the sample rate is not constant; allowed: " + kAllowed + rounding_note);
  }
  // Stamps rounded to a few digits: the first and last carry that rounding into dt whole (2 ppm at six
  // digits over 2.5 s); a least-squares line through all of them averages it out. Exact stamps keep
  // the end-point dt, which for i/fs on binary fractions is exactly 1/fs.
  double step = dt;
  if (std::max(digits.printed_half_unit(t[0]), digits.printed_half_unit(t[n - 1])) > 1e-9 * dt) {
    long double mean_t = 0.0L;
    for (const double v : t) mean_t += v;
    mean_t /= static_cast<long double>(n);
    const long double mean_i = static_cast<long double>(n - 1) / 2.0L;
    long double sxy = 0.0L, sxx = 0.0L;
    for (std::size_t i = 0; i < n; ++i) {
      const long double di = static_cast<long double>(i) - mean_i;
      sxy += di * (static_cast<long double>(t[i]) - mean_t);
      sxx += di * di;
    }
    step = static_cast<double>(sxy / sxx);
  }
  const double rate = 1.0 / (step * seconds_per_unit);
  if (!std::isfinite(rate) || !(rate > 0.0))
    throw data_error(where(n - 1) + ": " + col + " implies the sample rate " + number_text(rate) +
                     " Hz; allowed: stamps whose spacing gives a finite rate > 0");
  return rate;
}

std::string rate_text(double hz) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", hz);
  return buf;
}

}  // namespace rollspec::io
