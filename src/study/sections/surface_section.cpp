#include "src/study/sections/surface_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<SurfaceSection>& declared() {
  using T = SurfaceSection;
  static const auto k =
      SectionKeys<T>("surface")
          .section_if_present()
          .choice("method", &T::method, "isotropic surfaces", SurfaceMethod::spectral, kSurfaceMethods)
          .integer("nx", &T::nx, "grid points along x (even)", "128", 4, 1 << 14)
          .integer("ny", &T::ny, "grid points along y (even)", "128", 4, 1 << 14)
          .real("spacing", &T::spacing, "m", "grid spacing dx = dy", "1e-6", above(0.0))
          .real("anisotropy", &T::anisotropy, "-", "correlation length ratio x/y (spectral method)", "1", above(0.0))
          .real("correlation_x", &T::correlation_x, "m",
                "correlation length along x (seed method, 1/e; unset with [texture] source = profiles: the profiles' "
                "mean)",
                "1e-5", above(0.0))
          .real("correlation_y", &T::correlation_y, "m",
                "correlation length along y (seed method, 1/e; unset with [texture] source = profiles: the profiles' "
                "mean)",
                "1e-5", above(0.0))
          .real("sigma", &T::sigma, "m",
                "rms height of seed-method surfaces (unset with [texture] source = profiles: the profiles' mean "
                "standard deviation)",
                "3e-7", above(0.0))
          .integer("count", &T::count, "isotropic surfaces to generate", "0", 0, 1e6)
          .scene_declared();
  return k;
}
}  // namespace

std::vector<KeySpec> SurfaceSection::keys() { return declared().keys(); }

std::vector<KeySpec> SurfaceSection::count_keys() { return declared().keys_of(&SurfaceSection::count); }

SurfaceSection SurfaceSection::parse(const KeyReader& s) {
  SurfaceSection t = declared().read(s);
  t.present = !t.key_values().empty();
  if (!t.present) return t;
  t.sigma_default = !t.was_set(t.sigma);
  t.correlation_x_default = !t.was_set(t.correlation_x);
  t.correlation_y_default = !t.was_set(t.correlation_y);
  t.spacing_set = t.was_set(t.spacing);
  t.ny_set = t.was_set(t.ny);
  for (const auto& v : t.key_values()) t.texts[v.key] = v.text;
  return t;
}

}  // namespace rollspec::study
