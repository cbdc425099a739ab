#pragma once
// The grid of [surface] (spacing, nx, ny) as a scene that rolls over an isotropic surface checks it
// against its footprint, read once through SurfaceSection, which declares the keys.
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct SurfaceGridSection {
  double spacing = 0.0;
  long long nx = 0, ny = 0;
  KeyOrigin spacing_origin, nx_origin;

  static SurfaceGridSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
