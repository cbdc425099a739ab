// rollspec run: validate the study, plan, run the ensemble, write the result file atomically.

#include <filesystem>
#include <iostream>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/run/run_phases.hpp"
#include "src/cli/sweep_options.hpp"
#include "src/run/sweep_run.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

using run::kDefaultMaxSweepPoints;
using run::run_request;
using run::RunRequest;

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
  StudyCommandOptions cl(/*required=*/false);
  std::string out;
  cl.options.add_options()(
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
  std::vector<std::string> sweeps;
  std::size_t max_points = kDefaultMaxSweepPoints;
  add_sweep_option(cl.options, sweeps, max_points);
  if (!cl.parse(args, usage)) return 0;
  const bool resume = cl.vm.count("resume") > 0, restart = cl.vm.count("restart") > 0;
  if (resume && restart)
    throw usage_error("--resume and --restart exclude each other: finish the checkpoint, or discard it");
  long long only = -1;
  if (cl.vm.count("only")) {
    only = cl.vm["only"].as<long long>();
    if (only < 0) throw usage_error("--only " + std::to_string(only) + ": allowed: a realisation id >= 0");
    if (resume || restart)
      throw usage_error("--only runs one realisation without checkpoints; it takes no --resume or --restart");
  }

  if (out.empty() && cl.vm.count("out")) throw usage_error("--out is empty; allowed: the path of the result file");
  RunRequest request{
      cl.study, out, resume, restart, cl.vm.count("force") > 0, cl.vm.count("rebuild") > 0, cl.vm.count("quiet") > 0,
      only};
  request.max_sweep_points = max_points;
  return run_request(request, sweeps);
}

}  // namespace rollspec::cli
