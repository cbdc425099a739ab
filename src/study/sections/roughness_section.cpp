#include "src/study/sections/roughness_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> RoughnessSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      real_key(
          "roughness", "spacing", "m",
          "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per integration "
          "step, v / (sample_rate x substeps)",
          std::string("0"), 0.0, inf),
      choice_key("roughness", "band_limit",
                 "roughness the ball sees: output (wavelengths shorter than v / (sample_rate / 2) dropped, an ideal "
                 "anti-alias filter on the linear response; kernels/beam B40) or step (up to the sampling's pi/dx: the "
                 "response above sample_rate / 2 aliases into the bands)",
                 std::string("output"), {"output", "step"}),
  };
}

RoughnessSection RoughnessSection::parse(const KeyReader& s) {
  RoughnessSection p;
  p.spacing = s.real("roughness.spacing");
  p.band_limit = s.text("roughness.band_limit");
  p.spacing_origin = {s.where("roughness.spacing")};
  return p;
}

}  // namespace rollspec::study
