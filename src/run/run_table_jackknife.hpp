#pragma once
// `rollspec run` with [stiffness] table_error = jackknife (kernels/spectral/README.md D-30): after
// the ensemble with the full table, the same ensemble (study seed, K, realisation streams) once per
// leave-one-out sub-table, each by its own scene of the study with table_leave_out = i; the
// jackknife variance of their levels is handed to `scene`, whose write widens its intervals.
// The sub-table ensembles run as one ensemble whose realisations run every sub-table (D-30c pairs
// them); it keeps no checkpoint: an interrupted run resumes the full-table ensemble
// from its checkpoint and runs the sub-tables again.
#include <functional>
#include <string>
#include <vector>

#include "src/ensemble/ensemble_driver.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

namespace rollspec::run {

// The study as the run loaded it (its file or its checkpoint, its --set) with `extra` --set after
// them: a sub-table's study must be loaded as the full table's was, or its table inputs differ.
using StudyReload = std::function<study::Study(const std::vector<std::string>& extra)>;

// Nothing when the study does not ask for it, or for --only (one realisation has no interval).
void run_table_jackknife(const study::Study& s, const StudyReload& reload, scenes::EnsembleScene& scene,
                         const ensemble::EnsembleConfig& cfg, bool quiet, bool rebuild);

}  // namespace rollspec::run
