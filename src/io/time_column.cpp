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
std::string stamp_text(double v) { return significant_text(v, 10); }

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

double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const PrintedDigits& digits) {
  const std::size_t n = t.size();
  const std::string col = "time column '" + clip(name) + "'";
  if (n < 2)
    throw data_error(where(0) + ": " + col + " holds " + std::to_string(n) + " stamp; a sample rate needs at least 2");
  const double dt = (t[n - 1] - t[0]) / static_cast<double>(n - 1);
  const double unit = 2.0 * std::max(digits.printed_half_unit(t[0]), digits.printed_half_unit(t[n - 1]));
  if (unit > 0.0 && dt > 0.0 && dt < 2.0 * unit)
    refuse_irregular_coarse_steps(t, unit, dt, seconds_per_unit, col, where);
  GridNames names;
  names.column = col;
  names.allowed = kAllowed;
  names.text = stamp_text;
  const double step = uniform_grid_step(t, where, names, digits);
  const double rate = 1.0 / (step * seconds_per_unit);
  if (!std::isfinite(rate) || !(rate > 0.0))
    throw data_error(where(n - 1) + ": " + col + " implies the sample rate " + number_text(rate) +
                     " Hz; allowed: stamps whose spacing gives a finite rate > 0");
  return rate;
}

std::string rate_text(double hz) { return significant_text(hz, 10); }

}  // namespace rollspec::io
