#include "src/study/sections/strip_surface_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

StripSurfaceSection StripSurfaceSection::parse(const KeyReader& s) {
  StripSurfaceSection t;
  t.spacing_set = s.is_set("surface.spacing");
  t.ny_set = s.is_set("surface.ny");
  t.spacing = s.real("surface.spacing");
  t.anisotropy = s.real("surface.anisotropy");
  t.ny = s.integer("surface.ny");
  t.self_affine = s.text("texture.source") == "self-affine";
  t.rolloff_wavelength = s.real("texture.rolloff_wavelength");
  t.ny_origin = {s.where("surface.ny")};
  t.spacing_origin = {s.where("surface.spacing")};
  return t;
}

}  // namespace rollspec::study
