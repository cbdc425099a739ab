#include "src/io/time_column.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

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

double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const PrintedDigits& digits) {
  const std::size_t n = t.size();
  const std::string col = "time column '" + clip(name) + "'";
  if (n < 2)
    throw data_error(where(0) + ": " + col + " holds " + std::to_string(n) + " stamp; a sample rate needs at least 2");
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

std::string rate_text(double hz) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", hz);
  return buf;
}

}  // namespace rollspec::io
