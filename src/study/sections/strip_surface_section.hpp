#pragma once
// The [surface] and [texture] keys a strip stage's grid derives from (stiffness/blocked_force_geometry,
// path_table): the cell and the width where the study sets them, the anisotropy, and the self-affine
// roll-off. The keys themselves are the shared [surface] / [texture] tables (texture/texture_keys).
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct StripSurfaceSection {
  bool spacing_set = false, ny_set = false;  // false: derived from the contact radius
  double spacing = 0.0, anisotropy = 1.0;
  long long ny = 0;
  bool self_affine = false;         // [texture] source = self-affine
  double rolloff_wavelength = 0.0;  // [texture] rolloff_wavelength
  KeyOrigin ny_origin, spacing_origin;

  static StripSurfaceSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
