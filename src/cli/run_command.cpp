// rollspec run: validate the study, plan, run the ensemble, write the result file atomically.
#include <omp.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/cli/run_checkpoint.hpp"
#include "src/ensemble/checkpoint.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/output_target.hpp"
#include "src/io/provenance.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

namespace fs = std::filesystem;

namespace {
// --only writes one realisation: it replaces an earlier --only result, never a finished ensemble.
void refuse_replacing_an_ensemble(const std::string& write_path, const std::string& out) {
  if (!fs::exists(write_path)) return;
  const io::Hdf5Reader r(write_path);
  if (r.has_attribute("/run", "only_realisation")) return;
  const std::string n = r.has_attribute("/run", "realisations_computed")
                            ? std::to_string(static_cast<long long>(r.double_attribute("/run", "realisations_computed"))) + " "
                            : std::string();
  throw cannot_create("output file '" + out + "' (--out) holds a finished ensemble result (" + n +
                      "realisations computed); --only would replace it with one realisation; choose another --out (the "
                      "default is STUDY-only-ID.h5), or add --force to replace it");
}

// <out>.checkpoint of the file `out` names (a symbolic link followed), before the output is checked.
std::string resolved_checkpoint(const std::string& out) {
  std::error_code ec;
  const fs::path target = fs::is_symlink(out, ec) ? fs::canonical(out, ec) : fs::path(out);
  return (ec ? fs::path(out) : target).string() + ".checkpoint";
}
}  // namespace

int run_command(const Args& args) {
  const std::string usage =
      "usage: rollspec run STUDY.ini [--out FILE.h5] [--set section.key=value ...] [--resume | --restart] [--force] [--quiet]\n"
      "       rollspec run --resume --out FILE.h5 [--quiet]   (the checkpoint's own study; no study file needed)\n"
      "\n"
      "Runs the study's Monte-Carlo ensemble and writes the result file (HDF5, schema 1: /psd, /bands,\n"
      "provenance). The study is validated completely before any work starts. Completed chunks of\n"
      "realisations are checkpointed in FILE.h5.checkpoint/; after Ctrl-C (exit 130) or a crash,\n"
      "--resume finishes the ensemble with the checkpoint's own settings and a result bitwise identical\n"
      "to an uninterrupted run; --restart discards the checkpoint and starts over. An existing FILE.h5\n"
      "is replaced only if it is a rollspec result (or with --force).\n"
      "Threads: OMP_NUM_THREADS. The result data do not depend on the thread count.";
  po::options_description opts("options");
  StudyArgs study;
  std::string out;
  opts.add_options()("out,o", po::value(&out),
                     "result file (default: the study's name with .h5, or -only-ID.h5 with --only, in the current directory)")(
      "resume", "finish an interrupted run from its checkpoint (with the checkpoint's settings)")(
      "restart", "discard the checkpoint of an unfinished run and start over")(
      "force", "replace an existing --out file even if it is not a rollspec result, and run a study whose memory "
               "estimate exceeds the available memory")(
      "only", po::value<long long>(), "run just realisation ID (same random numbers as in the ensemble), to investigate it")(
      "rebuild", "rebuild cached stage tables whose inputs differ instead of refusing them")("quiet,q", "no progress output");
  po::positional_options_description pos;
  add_study_options(opts, pos, study, /*required=*/false);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  const bool resume = vm.count("resume") > 0, restart = vm.count("restart") > 0;
  if (resume && restart) throw usage_error("--resume and --restart exclude each other: finish the checkpoint, or discard it");
  long long only = -1;
  if (vm.count("only")) {
    only = vm["only"].as<long long>();
    if (only < 0) throw usage_error("--only " + std::to_string(only) + ": allowed: a realisation id >= 0");
    if (resume || restart) throw usage_error("--only runs one realisation without checkpoints; it takes no --resume or --restart");
  }

  // `run --resume --out FILE` needs no study file: the checkpoint holds the resolved study.
  const bool study_from_checkpoint = study.file.empty();
  if (study_from_checkpoint && !(resume && !out.empty()))
    throw usage_error("the study file is missing; allowed: rollspec run STUDY.ini [--out FILE.h5] ..., or rollspec run "
                      "--resume --out FILE.h5 to finish that file's checkpoint without its study file");
  study::Study s = study_from_checkpoint ? checkpoint_study(resolved_checkpoint(out), study.sets)
                                         : study::Study::load(study.file, study.sets, scenes::schema_for);
  // Before any workspace, FFT plan or table is allocated (an allocation failure inside FFTW aborts).
  scenes::check_memory(s, ensemble::ensemble_threads(), vm.count("force") > 0);
  if (out.empty())
    out = fs::path(study.file).stem().string() + (only >= 0 ? "-only-" + std::to_string(only) : std::string()) + ".h5";
  const fs::path out_dir = fs::absolute(out).parent_path();
  if (!fs::is_directory(out_dir)) throw cannot_create("output directory " + out_dir.string() + " does not exist (for --out " + out + ")");
  const bool quiet = vm.count("quiet") > 0;

  auto scene = scenes::find_scene(s.scene()).make(s);
  if (!scene->runs_ensemble() && !scene->single_run())
    s.refuse("study.scene", "has no ensemble to run; use rollspec " + std::string(s.scene() == "texture" ? "texture " : "stiffness ") + s.file());
  if (scene->single_run() && (resume || restart))
    throw usage_error("study " + s.file() + " (scene " + s.scene() + ") is one deterministic run with no checkpoint; drop --resume/--restart");
  io::OutputTarget target{out, io::kResultFileType};
  target.force = vm.count("force") > 0;
  target.clean_stale = ensemble::mpi_rank() == 0;
  target.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(s)) target.inputs.push_back(p);
  const std::string write_path = io::check_output_target(target);
  if (only >= 0 && !target.force) refuse_replacing_an_ensemble(write_path, out);

  if (scene->single_run()) {
    scene->prepare(quiet, vm.count("rebuild") > 0);
    io::Hdf5Writer w(write_path);
    io::write_provenance(w, io::kResultFileType, io::kResultSchemaVersion, s.canonical_text(),
                         static_cast<std::uint64_t>(s.integer("study.seed")));
    w.attribute("/", "scene", s.scene());
    scene->write_results(w, {});
    w.commit();
    if (!quiet) std::cout << "wrote " << out << "\n";
    return 0;
  }

  ensemble::EnsembleConfig cfg;
  CheckpointSession checkpoint;
  // The checkpoint (and its lock) belongs to the file written, not to the name given: two runs
  // on one result through two names (a symbolic link) are refused like two runs on one name.
  const std::string checkpoint_dir = write_path + ".checkpoint";
  if (only >= 0 && ensemble::mpi_rank() == 0) checkpoint.lock = std::make_unique<ensemble::CheckpointLock>(checkpoint_dir);
  if (only < 0) {
    // Resolves the study a --resume runs (the checkpoint's), so the scene is made after this.
    const std::string asked = s.canonical_text();
    checkpoint = open_checkpoint(checkpoint_dir, s, study.sets, resume, restart, quiet, study_from_checkpoint);
    cfg.checkpoint_dir = checkpoint.directory;
    if (s.canonical_text() != asked) {
      scenes::check_memory(s, ensemble::ensemble_threads(), vm.count("force") > 0);  // the checkpoint's study
      scene = scenes::find_scene(s.scene()).make(s);
    }
  }
  scene->prepare(quiet, vm.count("rebuild") > 0);
  cfg.realisations = static_cast<std::uint64_t>(s.integer("study.realisations"));
  cfg.chunk_size = static_cast<std::uint64_t>(s.integer("ensemble.chunk_size"));
  cfg.seed = static_cast<std::uint64_t>(s.integer("study.seed"));
  cfg.study_hash = scenes::study_result_hash(s);
  cfg.resume = resume;
  cfg.quiet = quiet;
  cfg.log_prefix = ensemble::rank_prefix();
  cfg.only = only;
  const ensemble::EnsembleSums sums = ensemble::run_ensemble(
      cfg, scene->values_per_realisation(),
      [&](std::uint64_t id, int thread, double* values) { scene->run_realisation(id, thread, values); });

  if (ensemble::mpi_rank() != 0) return 0;  // rank 0 holds the sums and writes the result
  {
    io::Hdf5Writer w(write_path);
    io::write_provenance(w, io::kResultFileType, io::kResultSchemaVersion, s.canonical_text(), cfg.seed);
    w.attribute("/", "scene", s.scene());
    scene->write_results(w, sums);
    w.write("/run/wall_seconds", {1}, &sums.seconds, "s", "wall time of the ensemble (this run; not part of the result data)");
    w.write("/run/reduce_seconds", {1}, &sums.reduce_seconds, "s", "gathering and adding chunk sums (part of wall_seconds)");
    w.attribute("/run", "threads", static_cast<std::int64_t>(omp_get_max_threads()));
    w.attribute("/run", "ranks", static_cast<std::int64_t>(ensemble::mpi_size()));
    w.attribute("/run", "realisations_computed", static_cast<std::int64_t>(sums.computed));
    if (cfg.only >= 0) w.attribute("/run", "only_realisation", static_cast<std::int64_t>(cfg.only));
    const ensemble::CriticalSection finishing;  // an interrupt waits until the bookkeeping is done
    w.commit();
    if (!cfg.checkpoint_dir.empty())
      ensemble::CheckpointStore(cfg.checkpoint_dir, cfg.study_hash).clear(/*keep_lock=*/true);
    if (checkpoint.lock) checkpoint.lock->remove();
  }
  if (!quiet)
    std::cout << "wrote " << out << " (" << io::counted(sums.count, "realisation") << ", " << sums.computed << " computed in "
              << sums.seconds << " s, " << io::counted(static_cast<unsigned long long>(ensemble::mpi_size()), "rank") << " x "
              << io::counted(static_cast<unsigned long long>(omp_get_max_threads()), "thread") << ")\n";
  return 0;
}

}  // namespace rollspec::cli
