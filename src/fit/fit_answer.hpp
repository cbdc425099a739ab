#pragma once
// rollspec fit's typed answer (fit_search.hpp): each key's estimate and interval, how ln L was read,
// and the tests at the estimate; cli/fit_report.hpp prints it as text or json.
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "src/compare/combined_test.hpp"

namespace rollspec::fit {

struct FitParameter {
  std::string key;
  double estimate, lower, upper;                // lower, upper: NaN when the fit gives no interval
  bool lower_at_range_end, upper_at_range_end;  // the interval is cut by the --vary range there
};

// How the fit read the likelihood (kernels/spectral D-27i): whether common random numbers held at the
// start, and where they did not, the response surface's runs, rounds and lack of fit.
struct FitObjective {
  double step = 0.0, incoherent_share = 0.0;
  bool common_random_numbers = true;
  int surface_runs = 0, rounds = 0;
  double lack_of_fit_p = 1.0;
};

// One measurement at its operating point, and the tests of it at the best fit: compare's D-26/D-31 test
// of the run there, and the same corrected for the fitted keys (D-27j).
struct FitPointReport {
  std::string measurement, at;
  compare::CombinedTest test;       // compare's, not corrected for the search
  spectral::BandTestResult fitted;  // D-27j
  std::string fitted_verdict;       // one line
  std::string question;             // the table's question (D-31; empty: the contact has no random table)
  std::size_t bands = 0;
  double records = 1.0;
};

struct FitReport {
  std::vector<FitParameter> parameters;
  std::vector<double> correlation;  // n x n; empty: the Hessian at the optimum is not positive definite
  std::vector<FitPointReport> points;
  FitObjective objective;
  std::string no_interval;    // non-empty: why the fit gives its estimate without an interval
  bool test_defined = false;  // every point has a test (corrected for the search, D-27j)
  double p_value = 1.0;       // one point: its test's; several: Fisher's combination of theirs
  std::string verdict;
  bool uncorrected_defined = false;  // the same of compare's tests, not corrected for the search
  double p_value_uncorrected = 1.0;
  std::string verdict_uncorrected;
  double log_likelihood = 0.0;
  int evaluations = 0, reused = 0;  // study runs; -ln L values taken from the journal
  std::size_t bands = 0;            // over all points
  std::uint64_t realisations = 0;
};

// Fills r.test_defined, r.p_value and r.verdict from the points' corrected tests, and the uncorrected
// fields from their compare tests (level 0.05).
void combine_point_tests(FitReport& r);

}  // namespace rollspec::fit
