#pragma once
// What `rollspec plan` finds of one study, as data: its memory estimate, checkpoint disk, the stages
// its scene runs, reuses from cache or skips, the tables a few timed solves estimate and, probed, the
// time of realisation 0. The command prints it (src/cli/plan_command.cpp); rollspec.studies.plan
// returns it to Python.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/run/study_args.hpp"
#include "src/scenes/scene.hpp"

namespace rollspec::run {

struct StudyPlan {
  std::string file, scene;
  long long realisations = 0;
  unsigned long long seed = 0;
  int threads = 1;                // OpenMP threads of the ensemble the estimates assume
  scenes::MemoryEstimate memory;  // estimated peak resident memory (bytes) and its terms
  double available_bytes = 0.0;   // what the machine has available now
  bool over_memory = false;       // run refuses it (unless forced); nothing below is filled
  bool ensemble = false;          // a Monte-Carlo scene (checkpoint and probe apply)
  unsigned long long chunks = 0;  // checkpoint chunks beside the result while the run lasts
  double chunk_bytes = 0.0;       // bytes of each
  std::vector<std::string> warnings;
  std::string note;  // [texture] source = profiles: what the scans resolve
  std::vector<scenes::StagePlan> stages;
  bool jackknife = false;  // [stiffness] table_error = jackknife (D-30, D-30f)
  scenes::TableJackknifePlan jk;
  std::vector<scenes::TableEstimate> tables;  // missing tables estimated from a few timed solves
  // probe: the seconds of realisation 0 (empty when not probed: `not_probed` says why, if asked).
  std::optional<double> seconds_per_realisation;
  std::string not_probed;
  double ensemble_seconds() const {  // the ensemble's estimated wall time on `threads`
    return seconds_per_realisation ? *seconds_per_realisation * static_cast<double>(realisations) / threads : 0.0;
  }
};

// A table stage (StagePlan::table: the stiffness table, or a table of the contact solver along the
// ball's path) that is not cached (status run). The probe never runs realisation 0 while one is
// missing: preparing the scene would build it.
bool missing_table(const scenes::StagePlan& stage);
bool any_missing_table(const std::vector<scenes::StagePlan>& stages);

// The longest a few solves of a missing table may take, by the model, for `plan` to time them (and
// estimate the table from them) without probing; a probe times them whatever they take.
double table_probe_limit(bool probe);

// The plan of the study `args` names (no sweep: a sweep's points are planned one by one). Validates
// the study (UserError as the command's); computes nothing but the probe's solves and writes no file.
StudyPlan plan_study(const StudyArgs& args, bool probe);

}  // namespace rollspec::run
