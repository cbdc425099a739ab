#pragma once
// [path_table] (scene ball-on-beam, law = path): the table P(delta, xi) of strip 0 along the ball's
// path (kernels/beam B41-B46), read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct PathTableSection : DeclaredSection<PathTableSection> {
  long long approaches = 0, step = 0;  // step 0: derived
  double strip_length = 0.0;           // m; 0: derived

  static SectionKeys<PathTableSection> declare();
};

}  // namespace rollspec::study
