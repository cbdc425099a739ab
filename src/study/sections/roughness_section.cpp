#include "src/study/sections/roughness_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<RoughnessSection>& declared() {
  using T = RoughnessSection;
  static const auto k =
      SectionKeys<T>("roughness")
          .real("spacing", &T::spacing, "m",
                "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per "
                "integration step, v / (sample_rate x substeps)",
                "0", at_least(0.0))
          .choice("band_limit", &T::band_limit, "roughness the ball sees", BandLimit::output, kBandLimits);
  return k;
}
}  // namespace

std::vector<KeySpec> RoughnessSection::keys() { return declared().keys(); }
RoughnessSection RoughnessSection::parse(const KeyReader& s) { return declared().read(s); }

}  // namespace rollspec::study
