#pragma once
// The [surface] and [texture] keys a strip stage's grid derives from (stiffness/blocked_force_geometry,
// path_table): the cell and the width where the study sets them, the anisotropy, and the self-affine
// roll-off; and the canonical texts of those keys, which the cached tables' input texts (their
// hashes) repeat. Made from the parsed SurfaceSection and TextureSection: those keys are read there only.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "src/study/sections/key_origin.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::study {

class KeyReader;

struct StripSurfaceSection {
  bool spacing_set = false, ny_set = false;  // false: derived from the contact radius
  double spacing = 0.0, anisotropy = 1.0;
  long long nx = 0, ny = 0;
  bool self_affine = false;         // [texture] source = self-affine
  double rolloff_wavelength = 0.0;  // [texture] rolloff_wavelength
  KeyOrigin ny_origin, spacing_origin;
  // [texture] keys in table order with their canonical value texts, the file keys (table, profiles)
  // left out: their contents enter the tables' input texts through the fingerprint.
  std::vector<std::pair<std::string, std::string>> texture_texts;

  static StripSurfaceSection of(const SurfaceSection& surface, const TextureSection& texture);
  static StripSurfaceSection parse(const KeyReader& s);
  // The canonical value text of [surface] `key` (as the resolved study writes it).
  const std::string& text(const std::string& key) const;

 private:
  std::map<std::string, std::string> surface_texts_;
};

}  // namespace rollspec::study
