#pragma once
// `rollspec plan` of a sweep: its points, each point's stages, and with --probe the estimated total time.
#include "src/run/sweep_run.hpp"

namespace rollspec::cli {

int plan_sweep(const run::SweepStudy& sweep, bool probe);

}  // namespace rollspec::cli
