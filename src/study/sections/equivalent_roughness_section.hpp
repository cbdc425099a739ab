#pragma once
// [equivalent_roughness] (scene ball-on-beam, filter = solver): the strips whose h_eq PSD is
// averaged, the line drawn from it and the stiffness correction, read once.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct EquivalentRoughnessSection {
  long long strips = 0;
  std::string line, stiffness;  // as written
  KeyOrigin line_origin;
  long long leave_out = -1;  // >= 0: the sub-table without this strip (D-30)
  KeyOrigin leave_out_origin;

  static std::vector<KeySpec> keys();
  static EquivalentRoughnessSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
