#pragma once
// [path_table] (scene ball-on-beam, law = path): the table P(delta, xi) of strip 0 along the ball's
// path (kernels/beam B41-B46), read once.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

// [path_table] ladder (kernels/beam B43, B43b).
enum class PathLadder { plane, first_contact };

inline constexpr ChoiceTable<PathLadder, 2> kPathLadders{{
    {PathLadder::plane, "plane",
     "one set of approaches from the strip's mean plane at every position, spanning the whole path's first contacts "
     "plus 3 delta_H (kernels/beam B43, B43a): the method before B43b, kept as its reference"},
    {PathLadder::first_contact, "first_contact",
     "each position's own approaches above its first contact, delta_c + j s with s = 3 delta_H / approaches, up to "
     "the first row carrying 5 W there (kernels/beam B43b): only the rows the dynamics use"},
}};

// [path_table] interpolation (kernels/beam B45, B45b): how P is carried between positions.
enum class PathInterpolation { cubic, linear };

inline constexpr ChoiceTable<PathInterpolation, 2> kPathInterpolations{{
    {PathInterpolation::cubic, "cubic",
     "Keys' six-point cubic convolution between equally spaced positions (kernels/beam B45b): in-band gain within "
     "0.02 dB up to a seventh of the positions' rate, so positions can stand further apart"},
    {PathInterpolation::linear, "linear",
     "linear between two positions (kernels/beam B45): the method before B45b, kept as its reference (its gain is "
     "sinc^2, -0.14 dB at a fourteenth of the positions' rate)"},
}};

struct PathTableSection : DeclaredSection<PathTableSection> {
  long long approaches = 0, step = 0;  // step 0: derived
  PathLadder ladder = PathLadder::first_contact;
  PathInterpolation interpolation = PathInterpolation::cubic;
  long long rows_every = 1;       // read every n-th row of the table (a convergence check, no new solve)
  long long positions_every = 1;  // read every n-th position of the table (a convergence check, no new solve)
  double strip_length = 0.0;      // m; 0: derived

  static SectionKeys<PathTableSection> declare();
};

}  // namespace rollspec::study
