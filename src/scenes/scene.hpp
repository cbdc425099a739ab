#pragma once
// A scene turns a validated study into realisations. It names the stages it needs; the planner
// (`rollspec plan`) prints them, and a stage a scene does not need is never computed.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "src/ensemble/ensemble_driver.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::io {
class Hdf5Writer;
}
namespace rollspec::study {
class Study;
}

namespace rollspec::scenes {

enum class StageStatus { run, cached, skipped };

struct StagePlan {
  std::string stage;   // texture, surface, stiffness_table, blocked_force, force, dynamics, spectra
  StageStatus status;
  std::string reason;
};

const char* to_string(StageStatus s);

class Scene {
 public:
  virtual ~Scene() = default;
  virtual std::vector<StagePlan> plan() const = 0;
  // Builds or loads what the realisations share (tables, plans); runs once before the ensemble.
  // `rebuild` replaces cached tables whose inputs no longer match instead of refusing them.
  virtual void prepare(bool /*quiet*/, bool /*rebuild*/) {}
  virtual std::size_t values_per_realisation() const = 0;
  // Thread-safe for distinct `thread` indices in [0, ensemble_threads()).
  virtual void run_realisation(std::uint64_t id, int thread, double* values) const = 0;
  virtual void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const = 0;
  // False for scenes with no ensemble (e.g. `texture`, written by `rollspec texture`).
  virtual bool runs_ensemble() const { return true; }
  // True for scenes whose result is one deterministic run, done in prepare() and written by
  // write_results() (e.g. `rolling-beam`).
  virtual bool single_run() const { return false; }
};

// A scene with stages but no ensemble (`texture`, `stiffness`): its work is done by its own command.
class StageOnlyScene : public Scene {
 public:
  std::size_t values_per_realisation() const override { return 0; }
  void run_realisation(std::uint64_t, int, double*) const override {}
  void write_results(io::Hdf5Writer&, const ensemble::EnsembleSums&) const override {}
  bool runs_ensemble() const override { return false; }
};

struct SceneInfo {
  std::string name;
  std::string description;
  std::function<std::vector<study::KeySpec>()> keys;  // scene-specific keys (common keys are added)
  std::function<std::unique_ptr<Scene>(const study::Study&)> make;
};

const std::vector<SceneInfo>& scene_registry();
const SceneInfo& find_scene(const std::string& name);  // throws config_error naming the scenes
std::vector<study::KeySpec> common_keys();
std::vector<study::KeySpec> schema_for(const std::string& scene);  // common + scene keys

// The study hash that result data depend on (everything but the realisation count and the
// ensemble layout), used for checkpoints.
std::uint64_t study_result_hash(const study::Study& s);

}  // namespace rollspec::scenes
