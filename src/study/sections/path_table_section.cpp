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
      .integer("step", &T::step,
               "law = path: path step in cells between tabulated positions; 0: at most a quarter of the contact "
               "radius",
               "0", 0, 1000)
      .real("strip_length", &T::strip_length, "m",
            "law = path: length of the rough strip; 0: the ball's path in the run ((end - start) + one step) plus "
            "the solver window",
            "0", at_least(0.0));
}
template struct DeclaredSection<PathTableSection>;

}  // namespace rollspec::study
