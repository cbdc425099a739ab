#include "src/study/sections/path_table_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<PathTableSection> PathTableSection::declare() {
  using T = PathTableSection;
  return SectionKeys<T>("path_table")
      .integer("approaches", &T::approaches,
               "law = path: approaches J of the table P(delta, xi) (kernels/beam B43), 2 or more", "8", 2, 64)
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
