#pragma once
// A time column (or .mat time variable) gives the sample rate of a measured signal and is never a
// channel. Recognised names, case-insensitive, spaces ignored: `t`, `time`, `zeit` (and temps, tiempo,
// tempo, tijd, tid), alone (seconds) or with a unit of s, ms, µs (us) or ns written as `_ms`, `[ms]`,
// `(ms)`, `/ms` or a last word (`time_s`, `Time (s)`, `t [ms]`, `zeit_ms`, `t [µs]`, `time/ms`;
// measurement_unit.hpp); in a CSV file also any column whose unit (name or units row) is a time.
//
// The stamps must increase and lie on a uniform grid: every stamp within kTimeGridTolerance sample
// intervals of t_0 + i·Δ, Δ = (t_last − t_0)/(n − 1), or within what rounding to the printed digits
// explains (half a unit of the last printed digit, StampDigits), whichever is larger: a logger that
// prints six significant digits at 25.6 kHz is off by up to 0.13 intervals at t = 2 s. A missing,
// repeated or inserted sample moves a stamp by half an interval or more, a change of rate further still.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rollspec::io {

constexpr double kTimeGridTolerance = 0.1;  // sample intervals

// Two sample rates agree if they differ by at most this fraction (--fs against the file's own rate).
constexpr double kRateTolerance = 1e-3;

// Seconds per unit of a time column's values (1, 1e-3, 1e-6, 1e-9), or 0 if `name` is not named like a
// time (with no unit, or a time unit).
double time_column_unit(const std::string& name);

// Seconds per unit of a time unit in any name (`stamp_us`: 1e-6, `Elapsed [s]`: 1), or 0 if it has none.
double time_unit_in_name(const std::string& name);

// "seconds", "milliseconds", "microseconds", "nanoseconds": a time unit's factor in messages.
std::string time_unit_words(double seconds_per_unit);

// How the stamps were printed (CsvTable::decimals, significant): stamp t was rounded by at most
// half of max(10^-decimals, 10^(floor(log10|t|) - significant + 1)), the coarser of the two ways
// loggers print (fixed decimals, or significant digits). The default: stored exactly (binary files).
struct StampDigits {
  int decimals = 1000;
  int significant = 1000;
  double half_unit(double t) const;          // the rounding bound of stamp t, in its own unit
  double printed_half_unit(double t) const;  // the same without the binary representation's few ulps
};

// The sample rate (Hz) the stamps imply. `where(i)` names stamp i in messages ("file.csv:12",
// "variable 't' element 12"); refusals are data errors naming the first offending stamp.
// Stamps printed so coarsely that one unit of their last digit is more than half a sample interval
// cannot show a missing sample (at 1 kHz in whole ms, 0..499, 501.. is also what a 999 Hz logger
// prints): they are read only if every step is the same; otherwise refused at the first step that
// differs from most, naming --fs.
double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const StampDigits& digits = {});

// "25600" or "25600.000001": a rate in messages, as many digits as it needs.
std::string rate_text(double hz);

}  // namespace rollspec::io
