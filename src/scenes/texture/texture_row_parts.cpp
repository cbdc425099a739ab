// What scene `texture`'s registry row (scene_registry.cpp) names besides its class and keys: its memory
// model and the references a run cites, and the relations of its dimensions.
#include <algorithm>

#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/scenes/texture/texture_scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/lines_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

using study::LinesSection;

std::vector<MemoryItem> texture_memory(const study::KeyReader& s, int /*threads*/) {
  const auto lines = study::LinesSection::parse(s);
  const double samples = lines.length / std::max(lines.spacing, 1e-300), count = static_cast<double>(lines.count);
  return {{8.0 * samples * (2.0 * count + 6.0),
           {key_text("lines", "count", count), key_text("lines", "length", lines.length),
            key_text("lines", "spacing", lines.spacing)},
           "line textures"},
          surfaces(study::SurfaceSection::parse(s))};
}

std::vector<DimensionRelation> texture_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  const double length = s.real(LinesSection::key(&LinesSection::length)),
               dx = s.real(LinesSection::key(&LinesSection::spacing));
  add_texture_relations(s, LinesSection::key(&LinesSection::length), length, "the line length", out);
  out.push_back({{LinesSection::key(&LinesSection::spacing), LinesSection::key(&LinesSection::length)},
                 length >= 16.0 * dx,
                 "a line of " + dim(length, "m") + " holds fewer than 16 samples at spacing " + dim(dx, "m")});
  add_surface_relations(s, true, 0.0, out, false);
  return out;
}

std::vector<std::string> texture_references(const study::KeyReader& s) {
  return texture_surface_references(s, study::SurfaceSection::parse(s).count);
}

}  // namespace rollspec::scenes
