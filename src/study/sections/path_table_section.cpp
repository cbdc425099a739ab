#include "src/study/sections/path_table_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<PathTableSection> PathTableSection::declare() {
  using T = PathTableSection;
  return SectionKeys<T>("path_table")
      .integer("approaches", &T::approaches,
               "law = path: approaches J of the table P(delta, xi) (kernels/beam B43), 2 or more", "8", 2, 64)
      .choice("ladder", &T::ladder, "law = path: where the table's approaches stand", PathLadder::first_contact,
              kPathLadders)
      .integer("rows_every", &T::rows_every,
               "law = path: read every n-th approach row of the table, from the same cached table (its node spacing "
               "times n, no new solve): what the band levels move by shows whether the table's approaches are fine "
               "enough (kernels/beam B43b); 1: every row",
               "1", 1, 4)
      .choice("interpolation", &T::interpolation, "law = path: how the force is carried between tabulated positions",
              PathInterpolation::cubic, kPathInterpolations)
      .integer("positions_every", &T::positions_every,
               "law = path: read every n-th position of the table, from the same cached table (its position spacing "
               "times n, no new solve): what the band levels move by shows whether the positions are close enough "
               "(kernels/beam B45b); 1: every position",
               "1", 1, 8)
      .integer("step", &T::step,
               "law = path: path step in cells between tabulated positions; 0: at most half the contact radius with "
               "interpolation = cubic, a quarter with linear",
               "0", 0, 1000)
      .real("strip_length", &T::strip_length, "m",
            "law = path: length of the rough strip; 0: the ball's path in the run ((end - start) + one step) plus "
            "the solver window",
            "0", at_least(0.0));
}
template struct DeclaredSection<PathTableSection>;

}  // namespace rollspec::study
