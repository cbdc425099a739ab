// What scene `rolling-pipe`'s registry row (scene_registry.cpp) names besides its class and keys: its memory
// model and the references a run cites.
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

using Item = MemoryItem;

std::vector<MemoryItem> rolling_pipe_memory(const study::KeyReader& s, int threads) {
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

std::vector<std::string> rolling_pipe_references(const study::KeyReader& s) {
  ReferenceIds ids = {"seed 000", "D-12..D-14"};
  if (study::PipeRoughnessSection::parse(s).line)
    add_references(ids, {"D-3"});
  else
    add_references(ids, isotropic_surface_references(study::SurfaceSection::parse(s).method));
  add_references(ids, ensemble_spectra_references(s));
  return ids;
}

}  // namespace rollspec::scenes
