#pragma once
// [blocked_force] (scene ball-on-beam): the blocked-force strip's grid where the study sets it
// (0: derived, stiffness/blocked_force_geometry), read once. The equivalent-roughness stage uses
// the same grid.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct BlockedForceSection : DeclaredSection<BlockedForceSection> {
  double strip_length = 0.0;                    // m; 0: derived
  long long window = 0, step = 0, segment = 0;  // 0: derived
  double answer_tolerance = 1e-3;               // contact BF-9; 0: the exhaustive search (the reference)
  long long leave_out = -1;                     // >= 0: the sub-table without this Welch segment of F0 (D-30d)

  static SectionKeys<BlockedForceSection> declare();
  static std::string leave_out_setting(long long i);  // "<section>.leave_out=i", a --set text
};

}  // namespace rollspec::study
