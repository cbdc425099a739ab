#pragma once
// `rollspec run`'s handling of <out>.checkpoint before any work (issue 16):
//   - the directory holds only files rollspec wrote (checkpoint.hpp), else it is refused;
//   - it is locked for the run (a concurrent run on the same --out is refused);
//   - a plain run over an unfinished checkpoint refuses ("--resume or --restart");
//   - --resume reruns the study stored in the manifest: the --set overrides of the interrupted run
//     are reused, a --set or study-file change is refused naming the keys, and so is a checkpoint of
//     another build of the code.
#include <memory>
#include <string>
#include <vector>

#include "src/ensemble/checkpoint_guard.hpp"
#include "src/study/study.hpp"

namespace rollspec::run {

struct CheckpointSession {
  std::unique_ptr<ensemble::CheckpointLock> lock;  // rank 0 only
  std::string directory;
};

// Opens (locks, checks, and for a fresh run writes the manifest of) the checkpoint of `study`.
// On --resume, replaces `study` with the checkpoint's own study, after comparing the checkpoint with
// the study file (or `study_text`, when the study was given as text) as it is now. Collective under MPI.
CheckpointSession open_checkpoint(const std::string& directory, study::Study& study,
                                  const std::vector<std::string>& sets, bool resume, bool restart, bool quiet,
                                  bool study_from_checkpoint = false, const std::string& study_text = {});

// `run --resume --out FILE` without a study file: the checkpoint's own resolved study (its manifest
// keeps the text and the study file's path, whose directory resolves relative paths), with `sets`
// (only keys the chunks do not depend on may differ; open_checkpoint checks).
study::Study checkpoint_study(const std::string& directory, const std::vector<std::string>& sets);

}  // namespace rollspec::run
