// Scene `white-noise`'s registry row, added to the registry when this file is linked into a program (the test
// build of the command, rollspec_toy): the whole of what the engine needs to know of a new scene.
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "tests/engine/toy_scene/white_noise.hpp"

namespace rollspec::scenes {

namespace {

// The ensemble's own storage (the toy leaves its records per thread out of its estimate).
std::vector<MemoryItem> memory(const study::KeyReader& s, int /*threads*/) {
  return {chunk_sums(study::StudySection::parse(s), study::EnsembleSection::parse(s), study::SpectrumSection::parse(s),
                     1.0, {})};
}

std::vector<std::string> references(const study::KeyReader& s) { return ensemble_spectra_references(s); }

const bool added = (add_scene(white_noise_row()), true);

}  // namespace

SceneInfo white_noise_row() {
  return {"white-noise",
          "test-only scene: one sensor reading white Gaussian noise of a PSD level; exact answer the level",
          SceneKind::ensemble,
          SceneCommand::run,
          white_noise_keys,
          make_white_noise,
          nullptr,
          {{"noise.level", {}}, {"signal.sample_rate", {}}, {"signal.duration", "4"}, {"spectrum.segment", "1024"}},
          memory,
          nullptr,
          nullptr,
          nullptr,
          references};
}

}  // namespace rollspec::scenes
