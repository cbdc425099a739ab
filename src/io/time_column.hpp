#pragma once
// A time column (or .mat time variable) gives the sample rate of a measured signal and is never a
// channel. Recognised names, case-insensitive, spaces ignored: `t` or `time`, alone (seconds) or with
// a unit of s or ms written as `_s`, `[s]`, `(s)` or `/s` (`time_s`, `Time (s)`, `t [ms]`, `time/ms`).
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

// Seconds per unit of a time column's values (1 or 1e-3), or 0 if `name` is not a time column name.
double time_column_unit(const std::string& name);

// The sample rate (Hz) the stamps imply; `digits`: how they were printed (CsvTable::decimals,
// significant). `where(i)` names stamp i in messages ("file.csv:12", "variable 't' element 12");
// refusals are data errors naming the first offending stamp.
double rate_from_time_stamps(const std::vector<double>& t, double seconds_per_unit, const std::string& name,
                             const std::function<std::string(std::size_t)>& where, const PrintedDigits& digits = {});

// "25600" or "25600.000001": a rate in messages, as many digits as it needs.
std::string rate_text(double hz);

}  // namespace rollspec::io
