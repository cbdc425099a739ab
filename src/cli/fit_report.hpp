#pragma once
// The printed form of a fit for people (json for programs: src/fit/fit_json.hpp).
#include <string>
#include <vector>

#include "src/fit/fit_answer.hpp"

namespace rollspec::cli {

using fit::FitObjective;
using fit::FitParameter;
using fit::FitPointReport;
using fit::FitReport;

std::string fit_text(const FitReport& r);

}  // namespace rollspec::cli
