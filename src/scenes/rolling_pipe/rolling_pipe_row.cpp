// Scene `rolling-pipe`'s registry row (scene.hpp SceneInfo): everything the engine asks of it.
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_grid_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

namespace {

using Item = MemoryItem;

std::vector<MemoryItem> memory(const study::KeyReader& s, int threads) {
  std::vector<Item> out;
  if (!study::PipeRoughnessSection::parse(s).line) {
    // One isotropic floor per realisation and thread, plus the generator's complex FFT grid.
    const auto f = study::SurfaceGridSection::parse(s);
    const double nx = static_cast<double>(f.nx), ny = static_cast<double>(f.ny);
    out.push_back({8.0 * nx * ny * (threads + 10.0),
                   {key_text("surface", "nx", nx), key_text("surface", "ny", ny)},
                   "rough floor per thread"});
  }
  const auto sensors = study::PipeSensorsSection::parse(s);
  out.push_back(chunk_sums(study::StudySection::parse(s), study::EnsembleSection::parse(s),
                           study::SpectrumSection::parse(s), static_cast<double>(sensors.positions.size()) + 2.0,
                           {positions_text("sensors", sensors.positions)}));
  return out;
}

std::vector<std::string> references(const study::KeyReader& s) {
  ReferenceIds ids = {"seed 000", "D-12..D-14"};
  if (study::PipeRoughnessSection::parse(s).line)
    add_references(ids, {"D-3"});
  else
    add_references(ids, isotropic_surface_references(study::SurfaceSection::parse(s).method));
  add_references(ids, ensemble_spectra_references(s));
  return ids;
}

}  // namespace

SceneInfo rolling_pipe_row() {
  return {"rolling-pipe",
          "tube of beam elements rolling with friction over a random rough surface; ensemble acceleration PSDs",
          SceneKind::ensemble,
          SceneCommand::run,
          rolling_pipe_keys,
          [](const study::KeyReader& s) { return make_rolling_pipe(s); },
          rolling_pipe_result_shape,
          rolling_pipe_first_keys(),
          memory,
          rolling_pipe_relations,
          nullptr,
          nullptr,
          references};
}

}  // namespace rollspec::scenes
