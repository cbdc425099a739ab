#include "src/study/sections/surface_grid_section.hpp"

#include "src/study/sections/surface_section.hpp"

namespace rollspec::study {

SurfaceGridSection SurfaceGridSection::parse(const KeyReader& s) {
  const SurfaceSection f = SurfaceSection::parse(s);
  return {f.spacing, f.nx, f.ny, f.origin(f.spacing), f.origin(f.nx)};
}

}  // namespace rollspec::study
