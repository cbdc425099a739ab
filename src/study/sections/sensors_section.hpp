#pragma once
// [sensors] (scene ball-on-beam): accelerometer positions along the beam and the mean over them,
// read once; positions against the span are checked by the scene, at origin(positions).
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct SensorsSection : DeclaredSection<SensorsSection> {
  std::vector<double> positions;  // m, as listed
  bool average = true;

  static SectionKeys<SensorsSection> declare();
};

}  // namespace rollspec::study
