#pragma once
// `rollspec run` as named phases with one rank policy (every rank validates; rank 0 alone writes):
//   1. resolve_run      the study (file, or a checkpoint's), the output and, for an ensemble, its
//                        checkpoint (a --resume runs the checkpoint's study, resolved here);
//   2. check_resources  the memory estimate of the study that runs, once;
//   3. make_scene       the scene, once, of the type its registry entry names;
//   4. prepare          its stages (tables), in the scene;
//   5. run_ensemble_phase / run_single_phase, each ending in a write on rank 0.
// `plan`, `modes`, `texture` and `stiffness` load their study through resolve_study and use
// phases 2 and 3 the same way.
#include <memory>
#include <string>
#include <vector>

#include "src/run/study_args.hpp"
#include "src/run/run_checkpoint.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

namespace rollspec::run {

// A sweep of more points than this is refused unless --max-points allows it: each point is one run
// of the study and one file, and each is checked before the first runs.
constexpr std::size_t kDefaultMaxSweepPoints = 1000;

struct RunRequest {
  StudyArgs study;
  std::string out;  // empty: from the study file's name
  bool resume = false, restart = false, force = false, rebuild = false, quiet = false;
  long long only = -1;        // >= 0: just this realisation
  bool spectra_only = false;  // a fit's evaluation: the result needs only /psd and /bands (write_spectra_only)
  std::size_t max_sweep_points = kDefaultMaxSweepPoints;  // --max-points
};

struct ResolvedRun {
  study::Study study;
  const scenes::SceneInfo* scene = nullptr;
  std::string out;         // as the user named it
  std::string write_path;  // the file written (a symbolic link resolved)
  CheckpointSession checkpoint;
};

// Phase 1 of the commands that write no ensemble result (plan, modes, stiffness, texture): the
// study file with its --set overrides, validated.
study::Study resolve_study(const StudyArgs& args);

// Phase 1. Refuses what cannot run (a scene without an ensemble, --resume of a single run, an
// output that must not be replaced) before any work.
ResolvedRun resolve_run(const RunRequest& request);

// Phase 2: refuses a study whose memory estimate exceeds the available memory (unless forced).
void check_resources(const study::KeyReader& s, bool force);

// Phase 3: the scene of `s`, as the type T its registry entry promises (Scene, EnsembleScene or
// SingleRunScene); an entry whose factory breaks that promise is an internal error.
template <class T>
std::unique_ptr<T> make_scene(const study::KeyReader& s) {
  std::unique_ptr<scenes::Scene> scene = scenes::find_scene(s.scene()).make(s);
  if (!dynamic_cast<T*>(scene.get())) throw std::logic_error("scene " + s.scene() + ": not of its registered kind");
  return std::unique_ptr<T>(static_cast<T*>(scene.release()));
}

// Phases 3-5 of each kind; each returns the exit code.
int run_single_phase(ResolvedRun& run, const RunRequest& request);
int run_ensemble_phase(ResolvedRun& run, const RunRequest& request);

// `rollspec run` after its options are read: the phases above, or a sweep's points (--sweep or [sweep]).
int run_request(const RunRequest& request, const std::vector<std::string>& sweeps = {});

}  // namespace rollspec::run
