#include "src/study/sections/strip_surface_section.hpp"

#include <stdexcept>

#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::study {

StripSurfaceSection StripSurfaceSection::parse(const KeyReader& s) {
  StripSurfaceSection t;
  t.spacing_set = s.is_set("surface.spacing");
  t.ny_set = s.is_set("surface.ny");
  t.spacing = s.real("surface.spacing");
  t.anisotropy = s.real("surface.anisotropy");
  t.nx = s.integer("surface.nx");
  t.ny = s.integer("surface.ny");
  t.self_affine = s.text("texture.source") == "self-affine";
  t.rolloff_wavelength = s.real("texture.rolloff_wavelength");
  t.ny_origin = {s.where("surface.ny")};
  t.spacing_origin = {s.where("surface.spacing")};
  for (const auto& k : texture_io::surface_keys()) t.surface_texts_[k.key] = s.text(k.full_name());
  for (const auto& k : texture_io::psd_keys()) t.texture_texts.emplace_back(k.key, s.text(k.full_name()));
  return t;
}

const std::string& StripSurfaceSection::text(const std::string& key) const {
  const auto it = surface_texts_.find(key);
  if (it == surface_texts_.end()) throw std::logic_error("not a [surface] key: " + key);
  return it->second;
}

}  // namespace rollspec::study
