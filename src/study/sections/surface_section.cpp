#include "src/study/sections/surface_section.hpp"

#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> SurfaceSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("surface", "method", "isotropic surfaces", SurfaceMethod::spectral, kSurfaceMethods),
      integer_key("surface", "nx", "grid points along x (even)", std::string("128"), 4, 1 << 14),
      integer_key("surface", "ny", "grid points along y (even)", std::string("128"), 4, 1 << 14),
      real_key("surface", "spacing", "m", "grid spacing dx = dy", std::string("1e-6"), 0.0, inf, false),
      real_key("surface", "anisotropy", "-", "correlation length ratio x/y (spectral method)", std::string("1"), 0.0,
               inf, false),
      real_key(
          "surface", "correlation_x", "m",
          "correlation length along x (seed method, 1/e; unset with [texture] source = profiles: the profiles' mean)",
          std::string("1e-5"), 0.0, inf, false),
      real_key(
          "surface", "correlation_y", "m",
          "correlation length along y (seed method, 1/e; unset with [texture] source = profiles: the profiles' mean)",
          std::string("1e-5"), 0.0, inf, false),
      real_key("surface", "sigma", "m",
               "rms height of seed-method surfaces (unset with [texture] source = profiles: the profiles' mean "
               "standard deviation)",
               std::string("3e-7"), 0.0, inf, false),
  };
}

std::vector<KeySpec> SurfaceSection::count_keys() {
  return {integer_key("surface", "count", "isotropic surfaces to generate", std::string("0"), 0, 1e6)};
}

SurfaceSection SurfaceSection::parse(const KeyReader& s) {
  SurfaceSection t;
  if (!s.has("surface.method")) return t;
  t.present = true;
  t.method = read_choice(s, "surface.method", kSurfaceMethods);
  t.nx = s.integer("surface.nx");
  t.ny = s.integer("surface.ny");
  if (s.has("surface.count")) t.count = s.integer("surface.count");
  t.spacing = s.real("surface.spacing");
  t.anisotropy = s.real("surface.anisotropy");
  t.correlation_x = s.real("surface.correlation_x");
  t.correlation_y = s.real("surface.correlation_y");
  t.sigma = s.real("surface.sigma");
  // Origin line 0: the documented default, not set.
  t.sigma_default = s.entry("surface.sigma").origin.line == 0;
  t.correlation_x_default = s.entry("surface.correlation_x").origin.line == 0;
  t.correlation_y_default = s.entry("surface.correlation_y").origin.line == 0;
  t.nx_origin = {s.where("surface.nx")};
  t.ny_origin = {s.where("surface.ny")};
  t.spacing_origin = {s.where("surface.spacing")};
  t.spacing_set = s.is_set("surface.spacing");
  t.ny_set = s.is_set("surface.ny");
  for (const auto& k : keys()) t.texts[k.key] = s.text(k.full_name());
  return t;
}

}  // namespace rollspec::study
