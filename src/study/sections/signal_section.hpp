#pragma once
// [signal] (scene ball-on-beam): output sample rate, integration substeps and hold, the integrator
// and the dopri5 reference's tolerance, read once.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct SignalSection {
  double sample_rate = 0.0, rtol = 0.0;
  long long substeps = 0;
  std::string hold, integrator;  // as written
  KeyOrigin substeps_origin, sample_rate_origin;

  static std::vector<KeySpec> keys();
  static SignalSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
