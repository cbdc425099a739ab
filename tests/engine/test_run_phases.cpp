// `rollspec run`'s phases in-process: the study a --resume runs is resolved from the checkpoint
// before the scene is made, so the scene is made once, and it is the checkpoint's.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "src/cli/commands.hpp"
#include "src/run/run_checkpoint.hpp"
#include "src/run/run_phases.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/scenes/scene.hpp"

using namespace rollspec;
namespace fs = std::filesystem;

namespace {
const char* kStudy =
    "[study]\nscene = random-oscillator\nrealisations = 8\nseed = 42\n[ensemble]\nchunk_size = 4\n"
    "[oscillator]\nmass = 1.5\nnatural_frequency = 40\ndamping_ratio = 0.05\n[force]\nlevel = 2.0\n"
    "[signal]\nsample_rate = 1024\nduration = 4\n[spectrum]\nsegment = 1024\nband_min = 8\nband_max = 400\n";

// A fresh directory holding the study, and the checkpoint an interrupted
// `run --set oscillator.mass=3` left (its manifest: the study with that override).
fs::path interrupted_run_with_override() {
  const fs::path dir = fs::temp_directory_path() / "rollspec_test_run_phases";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "s.ini") << kStudy;
  const std::vector<std::string> sets = {"oscillator.mass=3"};
  study::Study s = study::Study::load((dir / "s.ini").string(), sets, scenes::schema_for);
  const rollspec::run::CheckpointSession session =
      rollspec::run::open_checkpoint((dir / "r.h5.checkpoint").string(), s, sets, false, false, true);
  // The first chunk of 4 of the 8 realisations, as the interrupted run left it.
  const auto scene = rollspec::run::make_scene<scenes::EnsembleScene>(s);
  scene->prepare(true, false);
  ensemble::EnsembleConfig cfg;
  cfg.realisations = 4;
  cfg.chunk_size = 4;
  cfg.seed = 42;
  cfg.checkpoint_dir = session.directory;
  cfg.study_hash = scenes::study_result_hash(s);
  cfg.quiet = true;
  ensemble::run_ensemble(cfg, scene->values_per_realisation(),
                         [&](std::uint64_t id, int thread, double* v) { scene->run_realisation(id, thread, v); });
  return dir;
}
}  // namespace

TEST_CASE("run --resume: the checkpoint's study is resolved first and the scene is made once") {
  const fs::path dir = interrupted_run_with_override();
  rollspec::run::RunRequest q;
  q.study.file = (dir / "s.ini").string();
  q.out = (dir / "r.h5").string();
  q.resume = q.quiet = true;
  const long before = scenes::Scene::made();
  rollspec::run::ResolvedRun run = rollspec::run::resolve_run(q);
  CHECK(scenes::Scene::made() == before);                                   // resolving makes no scene
  CHECK(run.study.canonical_text().find("mass = 3") != std::string::npos);  // the checkpoint's study
  run.checkpoint = {};  // release the lock: run_command takes it again
  const long start = scenes::Scene::made();
  CHECK(cli::run_command({(dir / "s.ini").string(), "--out", (dir / "r.h5").string(), "--resume", "--quiet"}) == 0);
  CHECK(scenes::Scene::made() - start == 1);
  CHECK(!fs::exists(dir / "r.h5.checkpoint"));
  const io::Hdf5Reader r((dir / "r.h5").string());
  CHECK(r.string_attribute("/", "study").find("mass = 3") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("plan --probe makes one scene") {
  const fs::path dir = interrupted_run_with_override();
  const long start = scenes::Scene::made();
  CHECK(cli::plan_command({(dir / "s.ini").string(), "--probe"}) == 0);
  CHECK(scenes::Scene::made() - start == 1);
  fs::remove_all(dir);
}

TEST_CASE("a fit's evaluation (spectra only) writes the same spectra and bands as the full run, nothing else") {
  const fs::path dir = fs::temp_directory_path() / "rollspec_test_spectra_only";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "rig.ini")
      << "[study]\nscene = ball-on-beam\nrealisations = 6\nseed = 7\n"
         "[beam]\nsupport = clamped-clamped\nlength = 0.39\nwidth = 0.05\nthickness = 0.006\nyoungs_modulus = 210e9\n"
         "density = 7850\nmax_frequency = 3000\nloss_factor = 0.01\n"
         "[ball]\nradius = 0.02\nspeed = 1.0\nstart = 0.1\nend = 0.2\n"
         "[contact]\nlaw = linearised\nk0 = 6.8e6\n"
         "[texture]\nsource = self-affine\nhurst = 0.2\nrolloff_wavelength = 50e-3\nshort_wavelength = 4e-6\nrms = "
         "0.1e-6\n"
         "[signal]\nsample_rate = 8192\n[sensors]\npositions = 0.13, 0.26\n"
         "[spectrum]\nsegment = 512\nband_min = 80\nband_max = 2000\n";
  auto run = [&](const std::string& out, bool spectra_only) {
    rollspec::run::RunRequest q;
    q.study.file = (dir / "rig.ini").string();
    q.out = (dir / out).string();
    q.quiet = true;
    q.spectra_only = spectra_only;
    REQUIRE(rollspec::run::run_request(q) == 0);
    return io::Hdf5Reader(q.out);
  };
  const io::Hdf5Reader full = run("full.h5", false), fit = run("fit.h5", true);
  for (const char* d : {"/psd/frequency", "/psd/mean", "/psd/ci_lower", "/psd/ci_upper", "/psd/std", "/bands/level_db",
                        "/bands/ci_lower_db", "/bands/log_level_covariance"}) {
    CAPTURE(d);
    CHECK(full.read(d) == fit.read(d));  // the same bits
  }
  CHECK(full.exists("/roughness"));
  CHECK(full.exists("/reference/psd"));
  CHECK_FALSE(fit.exists("/roughness"));
  CHECK_FALSE(fit.exists("/reference"));
  fs::remove_all(dir);
}
