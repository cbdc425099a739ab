#pragma once
// The printed forms of a fit: text for people, json for programs.
#include <cstdint>
#include <string>
#include <vector>

#include "src/cli/compare_band_test.hpp"

namespace rollspec::cli {

struct FitParameter {
  std::string key;
  double estimate, lower, upper;
  bool lower_at_range_end, upper_at_range_end;  // the interval is cut by the --vary range there
};

struct FitReport {
  std::vector<FitParameter> parameters;
  std::vector<double> correlation;  // n x n; empty: the Hessian at the optimum is not positive definite
  CombinedTest test;                // at the best fit
  double log_likelihood = 0.0, records = 1.0;
  int evaluations = 0;  // study runs
  std::size_t bands = 0;
  std::uint64_t realisations = 0;
};

std::string fit_text(const FitReport& r);
std::string fit_json(const FitReport& r);

}  // namespace rollspec::cli
