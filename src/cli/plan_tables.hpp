#pragma once
// `rollspec plan` of a study or of a sweep's points: the measured estimates of the tables whose cost a
// few real solves tell better than the plan's model (EnsembleScene::probe_tables), in words. Which
// tables are missing and how long their probe may take is the engine's (src/run/study_plan.hpp).
#include <string>

#include "src/run/study_plan.hpp"
#include "src/scenes/scene.hpp"

namespace rollspec::cli {

using run::any_missing_table;
using run::missing_table;
using run::table_probe_limit;

// "table NAME: about X s CPU, Y s wall on T threads (probe: ...)", without a newline.
std::string table_probe_line(const scenes::TableEstimate& t);

}  // namespace rollspec::cli
