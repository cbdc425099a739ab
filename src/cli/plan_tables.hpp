#pragma once
// `rollspec plan` of a study or of a sweep's points: which stages are tables that are not built yet,
// and the measured estimates of those whose cost a few real solves tell better than the plan's model
// (EnsembleScene::probe_tables).
#include <string>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::cli {

// A table stage (StagePlan::table: the stiffness table, or a table of the contact solver along the
// ball's path) that is not cached (status run). --probe never runs realisation 0 while one is
// missing: preparing the scene would build it.
bool missing_table(const scenes::StagePlan& stage);
bool any_missing_table(const std::vector<scenes::StagePlan>& stages);

// The longest a few solves of a missing table may take, by the model, for `plan` to time them (and
// estimate the table from them) without --probe; --probe times them whatever they take.
double table_probe_limit(bool probe);

// "table NAME: about X s CPU, Y s wall on T threads (probe: ...)", without a newline.
std::string table_probe_line(const scenes::TableEstimate& t);

}  // namespace rollspec::cli
