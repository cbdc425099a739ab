#pragma once
// [roughness] (scene ball-on-beam): the line texture's spacing (0: one sample per integration
// step) and its band limit, read once.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct RoughnessSection {
  double spacing = 0.0;    // m; 0: derived from the step
  std::string band_limit;  // output or step
  KeyOrigin spacing_origin;

  static std::vector<KeySpec> keys();
  static RoughnessSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
