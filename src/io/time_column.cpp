#include "src/io/time_column.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "src/error.hpp"
#include "src/io/measurement_unit.hpp"
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

// Stamps printed to a unit u of more than half a sample interval: a missing sample lengthens a step
// by dt, rounding changes one by up to u, so only a column of identical steps (an exact grid) is read.
void refuse_irregular_coarse_steps(const std::vector<double>& t, double u, double dt, double seconds_per_unit,
                                   const std::string& col, const std::function<std::string(std::size_t)>& where) {
  std::map<long long, std::size_t> count;
  std::vector<long long> k(t.size(), 0);
  for (std::size_t i = 1; i < t.size(); ++i) ++count[k[i] = std::llround((t[i] - t[i - 1]) / u)];
  if (count.size() <= 1) return;
  const auto mode = std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) {
                      return a.second < b.second;
                    })->first;
  std::size_t i = 1;
  while (k[i] == mode) ++i;
  throw data_error(where(i) + ": " + col + " steps by " + stamp_text(t[i] - t[i - 1]) + " (from " +
                   stamp_text(t[i - 1]) + " to " + stamp_text(t[i]) + ") where most steps are " +
                   stamp_text(static_cast<double>(mode) * u) + ": stamps printed to the nearest " + stamp_text(u) +
                   " cannot show a missing or repeated sample at a sample interval of " + stamp_text(dt) +
                   " (a rate a little off prints such steps too); allowed: stamps printed with more digits, or " +
                   "--fs HZ, which overrides the time column (the stamps' mean step gives " +
                   rate_text(1.0 / (dt * seconds_per_unit)) + " Hz)");
}
}  // namespace

double time_column_unit(const std::string& name) {
  const NamedUnit n = unit_in_name(name);
  if (!time_like_name(n, name)) return 0.0;
  if (!n.unit) return n.written.empty() ? 1.0 : 0.0;  // `time (sensor 2)` is no time column
  return n.unit->quantity == Quantity::time ? n.unit->factor : 0.0;
}

double time_unit_in_name(const std::string& name) {
  const NamedUnit n = unit_in_name(name);
  return n.unit && n.unit->quantity == Quantity::time ? n.unit->factor : 0.0;
}

std::string time_unit_words(double seconds_per_unit) {
  return seconds_per_unit == 1e-3   ? "milliseconds"
         : seconds_per_unit == 1e-6 ? "microseconds"
         : seconds_per_unit == 1e-9 ? "nanoseconds"
                                    : "seconds";
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
  const double unit = 2.0 * std::max(digits.printed_half_unit(t[0]), digits.printed_half_unit(t[n - 1]));
  if (unit > 0.0 && dt > 0.0 && dt < 2.0 * unit)
    refuse_irregular_coarse_steps(t, unit, dt, seconds_per_unit, col, where);
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
