#pragma once
// A scene turns a validated study into realisations. It holds the stages it needs as objects
// (stage.hpp): `rollspec plan` prints their inspect(), prepare() resolves them, and a stage a scene
// does not need is never computed. To add a scene: its package folder src/scenes/<scene>/ and its
// SceneInfo row in scene_registry.cpp (everything the engine asks of a scene is a field there, each a
// function of the folder: no code outside the two tests its name); to add a stage: a Stage object
// added in the scene's constructor.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/ensemble/ensemble_driver.hpp"
#include "src/io/loss_effect.hpp"
#include "src/io/psd_result.hpp"
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/scenes/result_shape.hpp"
#include "src/scenes/stage.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::io {
class Hdf5Writer;
}
namespace rollspec::study {
class KeyReader;
}
namespace rollspec::beam {
class ModalBeam;
}

namespace rollspec::scenes {

// What every scene has: its stages. Scenes of the three kinds below add what their command runs.
class Scene {
 public:
  Scene() { made_.fetch_add(1, std::memory_order_relaxed); }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
  virtual ~Scene() = default;
  // Scenes made in this process: a command makes one (tests hold it to that).
  static long made() { return made_.load(std::memory_order_relaxed); }
  // inspect() of every stage, in pipeline order.
  std::vector<StagePlan> plan() const {
    std::vector<StagePlan> out;
    for (const auto& s : stages_) out.push_back(s->inspect());
    return out;
  }
  // Builds or loads what the run shares (tables, plans); runs once before the ensemble or the run.
  // `rebuild` replaces cached tables whose inputs no longer match instead of refusing them.
  // By default resolve() of every stage; scenes that finish their set-up afterwards call it first.
  virtual void prepare(bool quiet, bool rebuild) { resolve_stages(quiet, rebuild); }
  // The shared tables only, as prepare() builds or loads them first (rollspec.contact.tables): the
  // stages that are not tables resolve nothing.
  void resolve_tables(bool quiet, bool rebuild) { resolve_stages(quiet, rebuild); }
  // Legal but suspect physics the scene found in its study (printed on stderr when it was made).
  virtual std::vector<std::string> warnings() const { return {}; }

 protected:
  template <class S>
  S& add_stage(std::unique_ptr<S> stage) {
    S& s = *stage;
    stages_.push_back(std::move(stage));
    return s;
  }
  void add_stages(const std::vector<StagePlan>& fixed) {
    for (const auto& p : fixed) stages_.push_back(std::make_unique<FixedStage>(p));
  }
  void resolve_stages(bool quiet, bool rebuild) {
    for (auto& s : stages_) s->resolve(rebuild, quiet);
  }

 private:
  inline static std::atomic<long> made_{0};
  std::vector<std::unique_ptr<Stage>> stages_;
};

// [stiffness] table_error = jackknife (D-30): which random table the scene's runs share, over how many
// surfaces or strips, and the --set that makes the sub-table without one of them.
struct TableJackknifePlan {
  std::size_t n = 0;  // surfaces, strips or Welch segments
  std::string table;  // "stiffness table", "equivalent-roughness table", "blocked-force table"
  std::string unit;   // "surfaces", "strips", "Welch segments of F0"
  std::function<std::vector<std::string>(long long)> leave_out_sets;
  // Overlapping units (D-30d): the jackknife's variance times this, of `dof` degrees of freedom
  // (0: n - 1, independent units).
  double variance_factor = 1.0, dof = 0.0;
  // The table's error in different bands (kernels/spectral D-31c): independent for a spectral estimate
  // (a PSD averaged over Welch segments or strips: its bins' errors are uncorrelated), so only each
  // band's variance is kept; one curve's error for a stiffness table (it moves every band together),
  // kept as the sub-tables' whole band-by-band covariance.
  bool independent_bands = false;
};

// `plan`: a table the run would build, its build time measured on a few of its solves.
struct TableEstimate {
  std::string table;     // the stage
  double seconds = 0.0;  // estimated CPU seconds of the build
  int threads = 1;       // threads the build would use
  std::string how;       // what the probe solved, in words
};

// A Monte-Carlo scene: independent realisations, summed by the ensemble driver, written from the sums.
class EnsembleScene : public Scene {
 public:
  virtual std::size_t values_per_realisation() const = 0;
  // Thread-safe for distinct `thread` indices in [0, ensemble_threads()).
  virtual void run_realisation(std::uint64_t id, int thread, double* values) const = 0;
  virtual void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const = 0;
  // [stiffness] table_error = jackknife (kernels/spectral/README.md D-30): the spectra of `sums`
  // without writing them, and the table's own error that write_results adds to the intervals.
  // Only a scene with a rough stiffness table runs it; the others refuse the key before this.
  virtual io::PsdEnsemble spectra(const ensemble::EnsembleSums&) const {
    throw std::logic_error("this scene has no stiffness table to jackknife");
  }
  virtual TableJackknifePlan table_jackknife() const { throw std::logic_error("this scene has no table to jackknife"); }
  // The number of leading values of a realisation that are its spectra in linear units, in the
  // order of PsdEnsemble's bins and then its bands: what the jackknife pairs across runs (D-30c).
  virtual std::size_t linear_spectral_values() const {
    throw std::logic_error("this scene has no stiffness table to jackknife");
  }
  virtual void include_table_error(io::TableError) { throw std::logic_error("this scene has no stiffness table"); }
  // Whether `run` estimates a random table's own error ([stiffness] table_error: jackknife, or auto
  // with one random table; kernels/spectral D-30, D-31).
  virtual bool estimates_table_error() const { return false; }
  // kernels/spectral D-35: the --set that run the same realisations with a contact that never opens, when
  // the run (its sums) lost contact under a law that assumes a closed one; empty: no check. The measured
  // effect comes back through include_loss_effect before write_results.
  virtual std::vector<std::string> closed_contact_sets(const ensemble::EnsembleSums&) const { return {}; }
  virtual void include_loss_effect(io::LossEffect) {}
  // A fit's evaluation reads only the spectra and bands: write_results then leaves out what the scene
  // derives beside the ensemble (ball-on-beam: the roughness PSDs, the linearised reference, 90 % of
  // a short run's time, and the stored time histories, which it simulates again). A scene with no
  // such extras ignores it.
  virtual void write_spectra_only() {}
  // `plan`: the tables this run would build whose cost a few real solves measure better than the
  // plan's model, each probed only if the model puts its few solves at or under `max_probe_seconds`
  // (none by default).
  virtual std::vector<TableEstimate> probe_tables(double /*max_probe_seconds*/) const { return {}; }
};

// One deterministic computation (e.g. `rolling-beam`): run() once after prepare(), then written.
class SingleRunScene : public Scene {
 public:
  virtual void run(bool quiet) = 0;
  virtual void write_results(io::Hdf5Writer& w) const = 0;
};

// Scenes whose work is done by their own command from the stages (`texture`, `stiffness`) are
// plain Scenes: `rollspec run` refuses them.
enum class SceneKind { ensemble, single_run, stages_only };

// The command that runs a study of the scene: `run` for the ensemble and single-run scenes, the
// scene's own command for a stages-only one (rollspec init's template names it).
enum class SceneCommand { run, texture, stiffness };
const char* command_name(SceneCommand c);

// A key rollspec init writes first for a scene, uncommented, with the template's value.
struct FirstKey {
  std::string full_name;             // "section.key"
  std::optional<std::string> value;  // nullopt: the key table's default
};

// A first key named by the member its section reads it into (DeclaredSection::key), or by a member of
// one of its members.
template <class S, class T>
FirstKey first_key(T S::*field, std::optional<std::string> value = std::nullopt) {
  return {S::key(field), std::move(value)};
}
template <class S, class O, class T>
FirstKey first_key(O S::*outer, T O::*inner, std::optional<std::string> value = std::nullopt) {
  return {S::key(outer, inner), std::move(value)};
}

// Ball radius, effective modulus and weight of a study's contact (the ball on its flat or beam).
struct BallContact {
  double radius, effective_modulus, weight;
};

// Everything the engine asks of a scene. A field left empty says the scene has no such thing (the
// command that needs it refuses the study naming the scenes that have it).
struct SceneInfo {
  std::string name;
  std::string description;
  SceneKind kind;  // which of the scene types make() returns (make_scene checks it)
  SceneCommand command;
  std::function<std::vector<study::KeySpec>()> keys;  // scene-specific keys (common keys are added)
  std::function<std::unique_ptr<Scene>(const study::KeyReader&)> make;
  // The shape of /psd and /bands from the settings alone (empty for scenes that write no /psd).
  std::function<ResultShape(const study::KeyReader&)> result_shape;
  // rollspec init: the keys a rig is described by, after [study]'s (study_template_keys.cpp).
  std::vector<FirstKey> first_keys;
  // The peak memory terms that grow with the keys (memory_estimate.hpp), `threads` OpenMP threads.
  std::function<std::vector<MemoryItem>(const study::KeyReader&, int threads)> memory;
  // The plausibility relations of its lengths and speeds (dimension_plausibility.hpp); empty: none.
  std::function<std::vector<DimensionRelation>(const study::KeyReader&)> relations;
  // The ball and what it presses on, for a stiffness table (`rollspec stiffness`); empty: no contact table.
  std::function<BallContact(const study::KeyReader&)> contact_pair;
  // The modal beam (`rollspec modes`); empty: no modal beam.
  std::function<beam::ModalBeam(const study::KeyReader&)> modal_beam;
  // The papers and theory-note equations a run of the study uses (io/references.hpp ids, scene_references.hpp).
  std::function<std::vector<std::string>(const study::KeyReader&)> references;
};

const std::vector<SceneInfo>& scene_registry();
// A row added by a program before the registry is first read (a test-only scene in its own folder, linked into a
// test's build of the command: tests/engine/toy_scene); after the first read it throws std::logic_error.
void add_scene(SceneInfo row);
const SceneInfo& find_scene(const std::string& name);  // throws config_error naming the scenes
// "a or b": the scenes whose row has what `has` asks (for a command's refusal).
std::string scenes_with(const std::function<bool(const SceneInfo&)>& has);
std::vector<study::KeySpec> common_keys();
std::vector<study::KeySpec> schema_for(const std::string& scene);  // common + scene keys

// Keys that only the final write reads (outputs computed after the ensemble, from its sums or by
// rerunning realisations): checkpointed chunk sums do not depend on them, so --resume may change
// them, e.g. drop [output] reference when it does not fit in memory.
const std::vector<std::string>& finishing_keys();

// The study hash that chunk sums depend on (everything but the realisation count, the ensemble
// layout and the finishing keys), used for checkpoints.
std::uint64_t study_result_hash(const study::KeyReader& s);

}  // namespace rollspec::scenes
