#include "src/study/sections/sensors_section.hpp"

#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> SensorsSection::keys() {
  return {
      text_key("sensors", "positions", "accelerometer positions along the beam, m, comma-separated",
               std::string("0.2")),
      bool_key("sensors", "average", "add the mean PSD over sensors (seed 002 averages 5 sensors x 25 rolls)",
               std::string("true")),
  };
}

SensorsSection SensorsSection::parse(const KeyReader& s) {
  SensorsSection p;
  p.positions = s.numbers("sensors.positions");
  p.average = s.boolean("sensors.average");
  p.positions_origin = {s.where("sensors.positions")};
  return p;
}

}  // namespace rollspec::study
