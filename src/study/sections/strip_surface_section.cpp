#include "src/study/sections/strip_surface_section.hpp"

#include <stdexcept>

namespace rollspec::study {

StripSurfaceSection StripSurfaceSection::of(const SurfaceSection& surface, const TextureSection& texture) {
  StripSurfaceSection t;
  t.spacing_set = surface.spacing_set;
  t.ny_set = surface.ny_set;
  t.spacing = surface.spacing;
  t.anisotropy = surface.anisotropy;
  t.nx = surface.nx;
  t.ny = surface.ny;
  t.self_affine = texture.present && texture.source == TextureSource::self_affine;
  t.rolloff_wavelength = texture.rolloff_wavelength;
  t.ny_origin = surface.origin(surface.ny);
  t.spacing_origin = surface.origin(surface.spacing);
  t.surface_texts_ = surface.texts;
  for (const auto& v : texture.key_values())  // the files' contents enter through the fingerprint
    if (!texture.is_of(v, texture.table_path) && !texture.is_of(v, texture.profile_paths))
      t.texture_texts.emplace_back(v.key, v.text);
  return t;
}

StripSurfaceSection StripSurfaceSection::parse(const KeyReader& s) {
  return of(SurfaceSection::parse(s), TextureSection::parse(s));
}

const std::string& StripSurfaceSection::text(const std::string& key) const {
  const auto it = surface_texts_.find(key);
  if (it == surface_texts_.end()) throw std::logic_error("not a [surface] key: " + key);
  return it->second;
}

}  // namespace rollspec::study
