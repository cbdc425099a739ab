// `rollspec run` after its options are read (run_phases.hpp): the phases, or a sweep's points.
#include <filesystem>
#include <iostream>

#include "src/ensemble/mpi_context.hpp"
#include "src/run/run_phases.hpp"
#include "src/run/sweep_run.hpp"

namespace rollspec::run {

namespace {
// `run --resume --out X.h5` names a study only through X.h5's checkpoint or sweep; a study file
// named but gone since the interrupted run is the same case, said in one line.
bool resume_without_study(RunRequest& q) {
  if (!q.resume || q.out.empty() || !q.study.text.empty()) return false;  // a study from text is there
  if (q.study.file.empty()) return true;
  std::error_code ec;
  if (std::filesystem::exists(std::filesystem::symlink_status(q.study.file, ec))) return false;
  const bool checkpoint = std::filesystem::exists(q.out + ".checkpoint", ec),
             sweep = std::filesystem::exists(q.out + ".sweep", ec);
  if (!checkpoint && !sweep) return false;
  if (!q.quiet && ensemble::mpi_rank() == 0)
    std::cerr << "rollspec run: " << q.study.file << " no longer exists; resuming the study "
              << (sweep ? q.out + ".sweep" : q.out + ".checkpoint") << " keeps\n";
  q.study.file.clear();
  return true;
}
}  // namespace

int run_request(const RunRequest& given, const std::vector<std::string>& sweeps) {
  RunRequest request = given;
  SweepLimits limits{request.max_sweep_points, request.force, !request.quiet};
  if (sweeps.empty() && resume_without_study(request))
    if (const auto sweep = load_sweep_manifest(request.out, limits)) return run_sweep(*sweep, request);
  if (const auto sweep = load_sweep(request.study, sweeps, limits)) return run_sweep(*sweep, request);
  ResolvedRun run = resolve_run(request);
  check_resources(run.study, request.force);
  return run.scene->kind == scenes::SceneKind::single_run ? run_single_phase(run, request)
                                                          : run_ensemble_phase(run, request);
}

}  // namespace rollspec::run
