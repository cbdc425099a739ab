#include "src/study/sections/sensors_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<SensorsSection> SensorsSection::declare() {
  using T = SensorsSection;
  return SectionKeys<T>("sensors")
      .text("positions", &T::positions, "accelerometer positions along the beam, m, comma-separated", "0.2",
            number_list)
      .boolean("average", &T::average, "add the mean PSD over sensors (seed 002 averages 5 sensors x 25 rolls)",
               "true");
}
template struct DeclaredSection<SensorsSection>;

}  // namespace rollspec::study
