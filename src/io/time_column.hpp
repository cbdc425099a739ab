#pragma once
// A time column (or .mat time variable) gives the sample rate of a measured signal and is never a
// channel. Recognised names, case-insensitive, spaces ignored: `t`, `time`, `zeit` (and temps, tiempo,
// tempo, tijd, tid), alone (seconds) or with a unit of s, ms, µs (us) or ns written as `_ms`, `[ms]`,
// `(ms)`, `/ms` or a last word (`time_s`, `Time (s)`, `t [ms]`, `zeit_ms`, `t [µs]`, `time/ms`;
// measurement_unit.hpp); in a CSV file also any column whose unit (name or units row) is a time.
//
// The stamps must increase and lie on a uniform grid, within what rounding to their printed digits
// explains: the rule and the step of uniform_grid.hpp, shared with measured profiles' positions.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "src/io/uniform_grid.hpp"

namespace rollspec::io {

// Two sample rates agree if they differ by at most this fraction (--fs against the file's own rate).
constexpr double kRateTolerance = 1e-3;

// Seconds per unit of a time column's values (1, 1e-3, 1e-6, 1e-9), or 0 if `name` is not named like a
// time (with no unit, or a time unit).
double time_column_unit(const std::string& name);

// Seconds per unit of a time unit in any name (`stamp_us`: 1e-6, `Elapsed [s]`: 1), or 0 if it has none.
double time_unit_in_name(const std::string& name);

// "seconds", "milliseconds", "microseconds", "nanoseconds": a time unit's factor in messages.
std::string time_unit_words(double seconds_per_unit);

// The sample rate (Hz) the stamps imply; `digits`: how they were printed (CsvTable::decimals,
// significant). `where(i)` names stamp i in messages ("file.csv:12", "variable 't' element 12");
// refusals are data errors naming the first offending stamp.
// Stamps printed so coarsely that one unit of their last digit is more than half a sample interval
// cannot show a missing sample (at 1 kHz in whole ms, 0..499, 501.. is also what a 999 Hz logger
// prints): they are read only if every step is the same; otherwise refused at the first step that
// differs from most, naming --fs.
double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const PrintedDigits& digits = {});

// "25600" or "25600.000001": a rate in messages, as many digits as it needs.
std::string rate_text(double hz);

}  // namespace rollspec::io
