#pragma once
// What `rollspec fit` does once its options are read: the request checked (keys, ranges, measurements
// and their operating points), the study's runs in a temporary directory, the search (fit_search.hpp,
// kernels/spectral D-27) and the runs' own warnings. The command prints the answer
// (src/cli/fit_command.cpp); rollspec.studies.fit returns it to Python.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "src/fit/fit_answer.hpp"

namespace rollspec::fit {

struct FitRequest {
  std::string study;
  std::vector<std::string> measurements;  // MEASUREMENT / --measurement, in order
  std::vector<std::string> ats;           // --at of the same rank (none for a single measurement)
  std::vector<std::string> vary;          // --vary section.key=lo:hi[:log], 1 to 3
  std::vector<double> averages;           // --measured-averages: once for all or once per measurement
  std::vector<std::string> sets;          // --set for every run
  std::string sensor, column, journal;    // --sensor, --column (empty: the file's), --journal (empty: none)
  std::optional<double> measured_position;
  double fmin = 0.0, fmax = INFINITY;
  bool same_surface = false;
};

struct FitOutcome {
  FitReport report;
  std::string column;                 // the measurement's PSD column, as the reader chose it
  std::vector<std::string> warnings;  // the runs' warnings, as `rollspec fit` prints them to stderr
};

// Refuses a bad request (UsageError, exit 64; a missing file 66) before any run; an interrupt ends in a
// UserError with kExitInterrupted naming what the journal kept.
FitOutcome fit_study(const FitRequest& q);

}  // namespace rollspec::fit
