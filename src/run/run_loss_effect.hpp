#pragma once
// `rollspec run` after the ensemble, where the law assumes a closed contact and the ball lost contact
// (kernels/spectral D-35): the same realisations again, each with its own contact and with one that
// never opens (the scene's closed_contact_sets), side by side, so that what loss of contact moves is
// measured pair by pair from the run's own data; the scene's write then says it with its size.
#include "src/run/run_table_jackknife.hpp"

namespace rollspec::run {

// Nothing when the scene asks for no check (no loss of contact, or a law that models it), or for --only.
void run_loss_effect(const StudyReload& reload, scenes::EnsembleScene& scene, const ensemble::EnsembleConfig& cfg,
                     const ensemble::EnsembleSums& sums, bool quiet, bool rebuild);

}  // namespace rollspec::run
