#include "src/run/run_phases.hpp"
#include "src/run/run_loss_effect.hpp"
#include "src/run/run_table_jackknife.hpp"

#include <omp.h>

#include <filesystem>
#include <iostream>

#include "src/ensemble/checkpoint.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/output_target.hpp"
#include "src/io/provenance.hpp"
#include "src/io/references.hpp"
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/profile_source.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::run {

namespace fs = std::filesystem;

namespace {
// --only writes one realisation: it replaces an earlier --only result, never a finished ensemble.
void refuse_replacing_an_ensemble(const std::string& write_path, const std::string& out) {
  if (!fs::exists(write_path)) return;
  const io::Hdf5Reader r(write_path);
  if (r.has_attribute("/run", "only_realisation")) return;
  const std::string n =
      r.has_attribute("/run", "realisations_computed")
          ? std::to_string(static_cast<long long>(r.double_attribute("/run", "realisations_computed"))) + " "
          : std::string();
  throw cannot_create("output file '" + out + "' (--out) holds a finished ensemble result (" + n +
                      "realisations computed); --only would replace it with one realisation; choose another --out (the "
                      "default is STUDY-only-ID.h5), or add --force to replace it");
}

// [texture] source = profiles: what the scans resolve and the variance they leave unresolved (stderr).
void say_profile_note(const study::KeyReader& s, bool quiet) {
  if (quiet) return;
  const std::string note = texture_io::profile_note(study::TextureSection::parse(s));
  if (!note.empty()) std::cerr << "rollspec: note: " << note << "\n";
}

// <out>.checkpoint of the file `out` names (a symbolic link followed), before the output is checked.
std::string resolved_checkpoint(const std::string& out) {
  std::error_code ec;
  const fs::path target = fs::is_symlink(out, ec) ? fs::canonical(out, ec) : fs::path(out);
  return (ec ? fs::path(out) : target).string() + ".checkpoint";
}

study::Study load_study(const RunRequest& q) {
  // `run --resume --out FILE` needs no study file: the checkpoint holds the resolved study.
  if (!q.study.file.empty()) return resolve_study(q.study);
  if (!(q.resume && !q.out.empty()))
    throw usage_error(
        "the study file is missing; allowed: rollspec run STUDY.ini [--out FILE.h5] ..., or rollspec run "
        "--resume --out FILE.h5 to finish that file's checkpoint without its study file");
  study::Study s = checkpoint_study(resolved_checkpoint(q.out), q.study.sets);
  scenes::check_dimensions(s);
  return s;
}

// The checkpoint (and its lock) belongs to the file written, not to the name given: two runs on
// one result through two names (a symbolic link) are refused like two runs on one name.
void open_run_checkpoint(ResolvedRun& run, const RunRequest& q) {
  run.checkpoint = open_checkpoint(run.write_path + ".checkpoint", run.study, q.study.sets, q.resume, q.restart,
                                   q.quiet, q.study.file.empty(), q.study.text);
}

void write_run_attributes(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums, long long only) {
  w.write("/run/wall_seconds", {1}, &sums.seconds, "s",
          "wall time of the ensemble (this run; not part of the result data)");
  w.write("/run/reduce_seconds", {1}, &sums.reduce_seconds, "s",
          "gathering and adding chunk sums (part of wall_seconds)");
  w.attribute("/run", "threads", static_cast<std::int64_t>(omp_get_max_threads()));
  w.attribute("/run", "ranks", static_cast<std::int64_t>(ensemble::mpi_size()));
  w.attribute("/run", "realisations_computed", static_cast<std::int64_t>(sums.computed));
  if (only >= 0) w.attribute("/run", "only_realisation", static_cast<std::int64_t>(only));
}
}  // namespace

study::Study resolve_study(const StudyArgs& args) {
  study::Study s = !args.text.empty() ? study::Study::parse(args.file, args.text, args.sets, scenes::schema_for)
                                      : study::Study::load(args.file, args.sets, scenes::schema_for);
  scenes::check_dimensions(s);  // every length and speed against the others, before anything is made
  return s;
}

ResolvedRun resolve_run(const RunRequest& q) {
  ResolvedRun run{load_study(q), nullptr, q.out, {}, {}};
  const study::KeyReader& s = run.study;
  run.scene = &scenes::find_scene(s.scene());
  if (run.scene->kind == scenes::SceneKind::stages_only) {
    const auto study_keys = study::StudySection::parse(s);
    study_keys.origin(study_keys.scene)
        .refuse("has no ensemble to run; use rollspec " + std::string(scenes::command_name(run.scene->command)) + " " +
                s.file());
  }
  if (run.scene->kind == scenes::SceneKind::single_run && (q.resume || q.restart))
    throw usage_error("study " + s.file() + " (scene " + s.scene() +
                      ") is one deterministic run with no checkpoint; drop --resume/--restart");
  if (run.out.empty())
    run.out = fs::path(q.study.file).stem().string() +
              (q.only >= 0 ? "-only-" + std::to_string(q.only) : std::string()) + ".h5";
  const fs::path out_dir = fs::absolute(run.out).parent_path();
  if (!fs::is_directory(out_dir))
    throw cannot_create("output directory " + out_dir.string() + " does not exist (for --out " + run.out + ")");
  io::OutputTarget target{run.out, io::kResultFileType};
  target.force = q.force;
  target.clean_stale = ensemble::mpi_rank() == 0;
  target.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(s)) target.inputs.push_back(p);
  run.write_path = io::check_output_target(target);
  if (q.only >= 0 && !target.force) refuse_replacing_an_ensemble(run.write_path, run.out);
  // A --resume runs the checkpoint's study: resolved now, before anything is made from the study.
  // A fresh run's checkpoint opens after the resource check, so a refused study leaves none behind.
  if (run.scene->kind == scenes::SceneKind::ensemble && q.only < 0 && q.resume) open_run_checkpoint(run, q);
  return run;
}

void check_resources(const study::KeyReader& s, bool force) {
  // Before any workspace, FFT plan or table is allocated (an allocation failure inside FFTW aborts).
  scenes::check_memory(s, ensemble::ensemble_threads(), force);
}

int run_single_phase(ResolvedRun& run, const RunRequest& q) {
  // One deterministic computation: rank 0 makes, runs and writes it; other ranks have validated
  // the same study (phase 1) and stop.
  if (ensemble::mpi_rank() != 0) return 0;
  const auto scene = make_scene<scenes::SingleRunScene>(run.study);
  say_profile_note(run.study, q.quiet);
  scene->prepare(q.quiet, q.rebuild);
  scene->run(q.quiet);
  io::Hdf5Writer w(run.write_path);
  io::write_provenance(w, io::kResultFileType, io::kResultSchemaVersion, run.study.canonical_text(),
                       study::StudySection::parse(run.study).seed);
  w.attribute("/", "scene", run.study.scene());
  io::write_references(w, scenes::study_references(run.study));
  scene->write_results(w);
  texture_io::write_profile_record(w, "/profiles", study::TextureSection::parse(run.study));
  w.commit();
  if (!q.quiet) std::cout << "wrote " << run.out << "\n";
  return 0;
}

int run_ensemble_phase(ResolvedRun& run, const RunRequest& q) {
  const study::KeyReader& s = run.study;
  if (q.only >= 0 && ensemble::mpi_rank() == 0)
    run.checkpoint.lock = std::make_unique<ensemble::CheckpointLock>(run.write_path + ".checkpoint");
  if (q.only < 0 && !q.resume) open_run_checkpoint(run, q);
  const auto scene = make_scene<scenes::EnsembleScene>(s);
  if (ensemble::mpi_rank() == 0) say_profile_note(s, q.quiet);
  if (q.spectra_only) scene->write_spectra_only();
  scene->prepare(q.quiet, q.rebuild);
  ensemble::EnsembleConfig cfg;
  cfg.checkpoint_dir = run.checkpoint.directory;
  const study::StudySection study_keys = study::StudySection::parse(s);
  cfg.realisations = static_cast<std::uint64_t>(study_keys.realisations);
  cfg.chunk_size = static_cast<std::uint64_t>(study::EnsembleSection::parse(s).chunk_size);
  cfg.seed = study_keys.seed;
  cfg.study_hash = scenes::study_result_hash(s);
  cfg.resume = q.resume;
  cfg.quiet = q.quiet;
  cfg.log_prefix = ensemble::rank_prefix();
  cfg.only = q.only;
  const ensemble::EnsembleSums sums = ensemble::run_ensemble(
      cfg, scene->values_per_realisation(),
      [&](std::uint64_t id, int thread, double* values) { scene->run_realisation(id, thread, values); });
  const StudyReload reload = [&q](const std::vector<std::string>& extra) {
    RunRequest r = q;
    r.study.sets.insert(r.study.sets.end(), extra.begin(), extra.end());
    return load_study(r);
  };
  run_table_jackknife(run.study, reload, *scene, cfg, q.quiet, q.rebuild);  // a random table's error only
  run_loss_effect(reload, *scene, cfg, sums, q.quiet, q.rebuild);           // lost contact under law = linearised

  if (ensemble::mpi_rank() != 0) return 0;  // rank 0 holds the sums and writes the result
  {
    io::Hdf5Writer w(run.write_path);
    io::write_provenance(w, io::kResultFileType, io::kResultSchemaVersion, s.canonical_text(), cfg.seed);
    w.attribute("/", "scene", s.scene());
    io::write_references(w, scenes::study_references(s));
    scene->write_results(w, sums);
    texture_io::write_profile_record(w, "/profiles", study::TextureSection::parse(s));
    write_run_attributes(w, sums, cfg.only);
    const ensemble::CriticalSection finishing;  // an interrupt waits until the bookkeeping is done
    w.commit();
    if (!cfg.checkpoint_dir.empty())
      ensemble::CheckpointStore(cfg.checkpoint_dir, cfg.study_hash).clear(/*keep_lock=*/true);
    if (run.checkpoint.lock) run.checkpoint.lock->remove();
  }
  if (!q.quiet)
    std::cout << "wrote " << run.out << " (" << io::counted(sums.count, "realisation") << ", " << sums.computed
              << " computed in " << sums.seconds << " s, "
              << io::counted(static_cast<unsigned long long>(ensemble::mpi_size()), "rank") << " x "
              << io::counted(static_cast<unsigned long long>(omp_get_max_threads()), "thread") << ")\n";
  return 0;
}

}  // namespace rollspec::run
