#include "src/study/sections/sensors_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<SensorsSection>& declared() {
  using T = SensorsSection;
  static const auto k = SectionKeys<T>("sensors")
                            .text("positions", &T::positions,
                                  "accelerometer positions along the beam, m, comma-separated", "0.2", number_list)
                            .boolean("average", &T::average,
                                     "add the mean PSD over sensors (seed 002 averages 5 sensors x 25 rolls)", "true");
  return k;
}
}  // namespace

std::vector<KeySpec> SensorsSection::keys() { return declared().keys(); }
SensorsSection SensorsSection::parse(const KeyReader& s) { return declared().read(s); }

}  // namespace rollspec::study
