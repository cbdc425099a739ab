#include "src/study/sections/surface_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<SurfaceSection> SurfaceSection::declare() {
  using T = SurfaceSection;
  return SectionKeys<T>("surface")
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
}
template struct DeclaredSection<SurfaceSection>;

std::vector<KeySpec> SurfaceSection::count_keys() { return declared().keys_of(&SurfaceSection::count); }

void SurfaceSection::finish() {
  present = !key_values().empty();
  if (!present) return;
  sigma_default = !was_set(sigma);
  correlation_x_default = !was_set(correlation_x);
  correlation_y_default = !was_set(correlation_y);
  spacing_set = was_set(spacing);
  ny_set = was_set(ny);
  for (const auto& v : key_values()) texts[v.key] = v.text;
}

}  // namespace rollspec::study
