#pragma once
// A fit's answer for programs: the JSON `rollspec fit --format json` prints and rollspec.studies.fit
// returns, and the sentence on the objective that both it and the text form carry.
#include <string>

#include "src/fit/fit_answer.hpp"

namespace rollspec::fit {

// How ln L was taken: of the study's seed (common random numbers hold, D-27d) or smoothed by a
// quadratic response surface (D-27i), with the probe's figures.
std::string objective_text(const FitObjective& o);

// Keys in a fixed order, numbers as io::json_number (null where not finite), text not UTF-8 replaced.
std::string fit_json(const FitReport& r);

}  // namespace rollspec::fit
