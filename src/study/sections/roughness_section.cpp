#include "src/study/sections/roughness_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> RoughnessSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      real_key(
          "roughness", "spacing", "m",
          "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per integration "
          "step, v / (sample_rate x substeps)",
          std::string("0"), 0.0, inf),
      choice_key("roughness", "band_limit", "roughness the ball sees", BandLimit::output, kBandLimits),
  };
}

RoughnessSection RoughnessSection::parse(const KeyReader& s) {
  RoughnessSection p;
  p.spacing = s.real("roughness.spacing");
  p.band_limit = read_choice(s, "roughness.band_limit", kBandLimits);
  p.spacing_origin = {s.where("roughness.spacing")};
  return p;
}

}  // namespace rollspec::study
