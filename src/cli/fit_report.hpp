#pragma once
// The printed forms of a fit: text for people, json for programs.
#include <string>
#include <vector>

#include "src/fit/fit_answer.hpp"

namespace rollspec::cli {

using fit::FitObjective;
using fit::FitParameter;
using fit::FitPointReport;
using fit::FitReport;

std::string fit_text(const FitReport& r);
std::string fit_json(const FitReport& r);

}  // namespace rollspec::cli
