// rollspec run: validate the study, plan, run the ensemble, write the result file atomically.

#include <filesystem>
#include <iostream>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/cli/run_phases.hpp"
#include "src/cli/sweep_run.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

int run_command(const Args& args) {
  const std::string usage =
      "usage: rollspec run STUDY.ini [--out FILE.h5] [--set section.key=value ...] [--sweep section.key=v1,v2,...] "
      "[--resume | --restart] [--force] [--quiet]\n"
      "       rollspec run --resume --out FILE.h5 [--quiet]   (the checkpoint's own study; no study file needed)\n"
      "\n"
      "Runs the study's Monte-Carlo ensemble and writes the result file (HDF5, schema " +
      std::string(io::kResultSchemaVersion) +
      ": /psd, /bands,\n"
      "provenance). The study is validated completely before any work starts. Completed chunks of\n"
      "realisations are checkpointed in FILE.h5.checkpoint/; after Ctrl-C (exit 130) or a crash,\n"
      "--resume finishes the ensemble with the checkpoint's own settings and a result bitwise identical\n"
      "to an uninterrupted run; --restart discards the checkpoint and starts over. An existing FILE.h5\n"
      "is replaced only if it is a rollspec result (or with --force).\n"
      "A study with a [sweep] section (or --sweep) runs once per point and writes one file whose datasets\n"
      "gain a leading axis per swept key (see the Sweeps how-to).\n"
      "Threads: OMP_NUM_THREADS. The result data do not depend on the thread count.";
  po::options_description opts("options");
  StudyArgs study;
  std::string out;
  opts.add_options()(
      "out,o", po::value(&out),
      "result file (default: the study's name with .h5, or -only-ID.h5 with --only, in the current directory)")(
      "resume", "finish an interrupted run from its checkpoint (with the checkpoint's settings)")(
      "restart", "discard the checkpoint of an unfinished run and start over")(
      "force",
      "replace an existing --out file even if it is not a rollspec result, and run a study whose memory "
      "estimate exceeds the available memory")(
      "only", po::value<long long>(),
      "run just realisation ID (same random numbers as in the ensemble), to investigate it")(
      "rebuild", "rebuild cached stage tables whose inputs differ instead of refusing them")("quiet,q",
                                                                                             "no progress output");
  po::positional_options_description pos;
  add_study_options(opts, pos, study, /*required=*/false);
  std::vector<std::string> sweeps;
  std::size_t max_points = kDefaultMaxSweepPoints;
  add_sweep_option(opts, sweeps, max_points);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  const bool resume = vm.count("resume") > 0, restart = vm.count("restart") > 0;
  if (resume && restart)
    throw usage_error("--resume and --restart exclude each other: finish the checkpoint, or discard it");
  long long only = -1;
  if (vm.count("only")) {
    only = vm["only"].as<long long>();
    if (only < 0) throw usage_error("--only " + std::to_string(only) + ": allowed: a realisation id >= 0");
    if (resume || restart)
      throw usage_error("--only runs one realisation without checkpoints; it takes no --resume or --restart");
  }

  if (out.empty() && vm.count("out")) throw usage_error("--out is empty; allowed: the path of the result file");
  RunRequest request{study, out, resume, restart, vm.count("force") > 0, vm.count("rebuild") > 0, vm.count("quiet") > 0,
                     only};
  request.max_sweep_points = max_points;
  return run_request(request, sweeps);
}

namespace {
// `run --resume --out X.h5` names a study only through X.h5's checkpoint or sweep; a study file
// named but gone since the interrupted run is the same case, said in one line.
bool resume_without_study(RunRequest& q) {
  if (!q.resume || q.out.empty()) return false;
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

}  // namespace rollspec::cli
