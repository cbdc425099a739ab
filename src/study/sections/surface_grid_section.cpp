#include "src/study/sections/surface_grid_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

SurfaceGridSection SurfaceGridSection::parse(const KeyReader& s) {
  SurfaceGridSection g;
  g.spacing = s.real("surface.spacing");
  g.nx = s.integer("surface.nx");
  g.ny = s.integer("surface.ny");
  g.spacing_origin = {s.where("surface.spacing")};
  g.nx_origin = {s.where("surface.nx")};
  return g;
}

}  // namespace rollspec::study
