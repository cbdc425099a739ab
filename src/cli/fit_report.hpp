#pragma once
// The printed forms of a fit: text for people, json for programs.
#include <cstdint>
#include <string>
#include <vector>

#include "src/compare/combined_test.hpp"

namespace rollspec::cli {

using compare::ChosenBands;
using compare::CombinedTest;
using compare::chosen_bands;
using compare::combined_test;

struct FitParameter {
  std::string key;
  double estimate, lower, upper;
  bool lower_at_range_end, upper_at_range_end;  // the interval is cut by the --vary range there
};

// One measurement at its operating point, and D-26's test of it at the best fit.
struct FitPointReport {
  std::string measurement, at;
  CombinedTest test;
  std::size_t bands = 0;
  double records = 1.0;
};

struct FitReport {
  std::vector<FitParameter> parameters;
  std::vector<double> correlation;  // n x n; empty: the Hessian at the optimum is not positive definite
  std::vector<FitPointReport> points;
  bool test_defined = false;  // every point has a test
  double p_value = 1.0;       // one point: its test's; several: Fisher's combination of theirs
  std::string verdict;
  double log_likelihood = 0.0;
  int evaluations = 0, reused = 0;  // study runs; -ln L values taken from the journal
  std::size_t bands = 0;            // over all points
  std::uint64_t realisations = 0;
};

// Fills r.test_defined, r.p_value and r.verdict from r.points (level 0.05).
void combine_point_tests(FitReport& r);

std::string fit_text(const FitReport& r);
std::string fit_json(const FitReport& r);

}  // namespace rollspec::cli
