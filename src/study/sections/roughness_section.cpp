#include "src/study/sections/roughness_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<RoughnessSection> RoughnessSection::declare() {
  using T = RoughnessSection;
  return SectionKeys<T>("roughness")
      .real("spacing", &T::spacing, "m",
            "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per "
            "integration step, v / (sample_rate x substeps)",
            "0", at_least(0.0))
      .choice("band_limit", &T::band_limit, "roughness the ball sees", BandLimit::output, kBandLimits);
}
template struct DeclaredSection<RoughnessSection>;

}  // namespace rollspec::study
