#pragma once
// Samples that should lie on a uniform grid, as a file printed their abscissae: time stamps of a
// measured signal (time_column.hpp) and positions of a measured profile (texture_keys.cpp). One rule
// for both:
//
// The values must increase and lie on a uniform grid: every value within kGridTolerance steps of
// v_0 + i·Δ, Δ = (v_last − v_0)/(n − 1), or within what rounding to the printed digits explains (half a
// unit of the last printed digit, PrintedDigits), whichever is larger: a logger that prints six
// significant digits at 25.6 kHz is off by up to 0.13 intervals at t = 2 s; a stylus export that prints
// 0.156 um steps to 0.1 um is off by up to 0.32 steps. A missing, repeated or inserted sample moves a
// value by half a step or more, a change of rate further still.
//
// The step returned: the end-point Δ for values stored exactly; for rounded ones the least-squares
// slope through all of them (the first and last values carry their rounding into Δ whole).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rollspec::io {

constexpr double kGridTolerance = 0.1;  // steps

// How the values were printed (CsvTable::decimals, significant): value v was rounded by at most
// half of max(10^-decimals, 10^(floor(log10|v|) - significant + 1)), the coarser of the two ways
// loggers print (fixed decimals, or significant digits). The default: stored exactly (binary files).
struct PrintedDigits {
  int decimals = 1000;
  int significant = 1000;
  double half_unit(double v) const;          // the rounding bound of value v, in its own unit
  double printed_half_unit(double v) const;  // the same without the binary representation's few ulps
  bool exact() const { return decimals >= 400; }
};

// How messages name the grid: "time column 'time_s'" with its stamps t and step dt, or
// "column 'position_m'" with its positions x and step dx; `text` prints a value or a step.
struct GridNames {
  std::string column;                                      // "time column 'time_s'"
  std::string values = "stamps";                           // the values, plural
  std::string previous = "previous stamp";                 // "(previous stamp P)"
  std::string interval = "sample interval";                // unit of the offsets: "0.3 sample intervals"
  std::string record = "record";                           // what the values span
  std::string grid = "t_0 + i*dt";                         // the grid's formula
  std::string step = "dt";                                 // the step's symbol
  std::string allowed;                                     // "strictly increasing, uniformly spaced stamps (...)"
  std::string uneven = "the sample rate is not constant";  // what a value off the grid means
  std::function<std::string(double)> text;                 // a value or step as printed in messages
};

// The grid step the values imply (in their own unit); `fitted`, if given, says whether it is the
// least-squares slope (rounded values). `where(i)` names value i ("file.csv:12", "variable 't'
// element 12"); refusals are data errors naming the first offending value.
double uniform_grid_step(const std::vector<double>& v, const std::function<std::string(std::size_t)>& where,
                         const GridNames& names, const PrintedDigits& digits = {}, bool* fitted = nullptr);

}  // namespace rollspec::io
