#include <atomic>
#include <sstream>
#include <stdexcept>

#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "kernels/beam/modal_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/random_oscillator/random_oscillator.hpp"
#include "src/scenes/scene.hpp"
#include "src/scenes/rolling_beam/rolling_beam.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "src/scenes/stiffness/stiffness_scene.hpp"
#include "src/scenes/texture/texture_scene.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/output_section.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/key_reader.hpp"
#include "src/version.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {
std::vector<SceneInfo>& added_scenes() {
  static std::vector<SceneInfo> rows;
  return rows;
}
std::atomic<bool> registry_read{false};
}  // namespace

void add_scene(SceneInfo row) {
  if (registry_read.load()) throw std::logic_error("add_scene(" + row.name + ") after the scene registry was read");
  added_scenes().push_back(std::move(row));
}

// One row per scene: everything the engine asks of it (scene.hpp SceneInfo), each field a function of the
// scene's package folder src/scenes/<scene>/. A scene is its folder and its row here.
const std::vector<SceneInfo>& scene_registry() {
  static const std::vector<SceneInfo> scenes = [] {
    registry_read.store(true);
    std::vector<SceneInfo> rows = {
        {"random-oscillator",
         "linear single-degree-of-freedom oscillator driven by a random force from a PSD; exact answer |H|^2 S_F",
         SceneKind::ensemble, SceneCommand::run, random_oscillator_keys, make_random_oscillator,
         random_oscillator_result_shape, random_oscillator_first_keys(), random_oscillator_memory, nullptr, nullptr,
         nullptr, random_oscillator_references},
        {"ball-on-beam", "smooth rigid ball rolling over a rough modal beam; sensor acceleration PSDs (seeds 001, 002)",
         SceneKind::ensemble, SceneCommand::run, ball_on_beam_keys, make_ball_on_beam, ball_on_beam_result_shape,
         ball_on_beam_first_keys(), ball_on_beam_memory, ball_on_beam_relations, ball_on_beam_contact_pair,
         study_modal_beam, ball_on_beam_references},
        {"rolling-beam", "geometrically exact beam or rigid disc rolling and sliding on a plane (seed 000)",
         SceneKind::single_run, SceneCommand::run, rolling_beam_keys, make_rolling_beam, nullptr,
         rolling_beam_first_keys(), rolling_beam_memory, rolling_beam_relations, nullptr, nullptr,
         rolling_beam_references},
        {"rolling-pipe",
         "tube of beam elements rolling with friction over a random rough surface; ensemble acceleration PSDs",
         SceneKind::ensemble, SceneCommand::run, rolling_pipe_keys, make_rolling_pipe, rolling_pipe_result_shape,
         rolling_pipe_first_keys(), rolling_pipe_memory, rolling_pipe_relations, nullptr, nullptr,
         rolling_pipe_references},
        {"stiffness", "contact stiffness table only: smooth ball on a rough flat (rollspec stiffness)",
         SceneKind::stages_only, SceneCommand::stiffness, stiffness_scene_keys, make_stiffness_scene, nullptr,
         stiffness_first_keys(), stiffness_memory, stiffness_relations, stiffness_contact_pair, nullptr,
         stiffness_references},
        {"texture", "roughness only: line textures and isotropic surfaces from a PSD (rollspec texture)",
         SceneKind::stages_only, SceneCommand::texture, texture_scene_keys, make_texture_scene, nullptr,
         texture_first_keys(), texture_memory, texture_relations, nullptr, nullptr, texture_references},
    };
    for (auto& row : added_scenes()) rows.push_back(std::move(row));
    return rows;
  }();
  return scenes;
}

const char* command_name(SceneCommand c) {
  switch (c) {
    case SceneCommand::run:
      return "run";
    case SceneCommand::texture:
      return "texture";
    case SceneCommand::stiffness:
      return "stiffness";
  }
  return "run";
}

std::string scenes_with(const std::function<bool(const SceneInfo&)>& has) {
  std::vector<std::string> names;
  for (const auto& s : scene_registry())
    if (has(s)) names.push_back(s.name);
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

const SceneInfo& find_scene(const std::string& name) {
  std::string names;
  for (const auto& s : scene_registry()) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw config_error("[study] scene = " + name + ": unknown scene; allowed: one of " + names);
}

std::vector<KeySpec> common_keys() {
  std::vector<std::string> names;
  for (const auto& s : scene_registry()) names.push_back(s.name);
  return joined_keys({StudySection::keys_with_scenes(names), EnsembleSection::keys(), SpectrumSection::keys()});
}

std::vector<KeySpec> schema_for(const std::string& scene) {
  std::vector<KeySpec> keys = common_keys();
  const auto extra = find_scene(scene).keys();
  keys.insert(keys.end(), extra.begin(), extra.end());
  return keys;
}

const std::vector<std::string>& finishing_keys() {
  // reference: computed from the sums' count; time_histories: realisations 0..n-1 rerun at the write.
  using study::OutputSection;
  static const std::vector<std::string> keys = {OutputSection::key(&OutputSection::reference),
                                                OutputSection::key(&OutputSection::time_histories)};
  return keys;
}

std::uint64_t study_result_hash(const KeyReader& s) {
  using study::EnsembleSection;
  using study::StudySection;
  std::vector<std::string> excluded = {StudySection::key(&StudySection::realisations),
                                       StudySection::key(&StudySection::description),
                                       EnsembleSection::key(&EnsembleSection::chunk_size)};
  excluded.insert(excluded.end(), finishing_keys().begin(), finishing_keys().end());
  return io::fnv1a64(std::string(kVersion) + "\n" + s.canonical_text_without(excluded));
}

}  // namespace rollspec::scenes
