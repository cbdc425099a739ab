#pragma once
// A comparison (comparison.hpp) as the JSON object `rollspec compare --format json` prints and
// rollspec.studies.compare returns: the bands with their intervals and inside flags, the combined test,
// the level offset, the measured and noise spectra as compared, the warnings and the references. The
// JSON is ordered as written; a value that is not finite is null (JSON has no NaN or infinity).
#include <nlohmann/json.hpp>

#include "src/compare/comparison.hpp"

namespace rollspec::compare {

nlohmann::ordered_json comparison_json(const Comparison& c);

}  // namespace rollspec::compare
