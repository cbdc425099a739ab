#include "src/study/sections/lines_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<LinesSection> LinesSection::declare() {
  using L = LinesSection;
  return SectionKeys<L>("lines")
      .integer("count", &L::count, "line textures to generate", "10", 0, 1e6)
      .real("length", &L::length, "m", "length of each line texture", "0.4", above(0.0))
      .real("spacing", &L::spacing, "m", "sample spacing dx of the lines (dx <= pi / k_max)", "1e-5", above(0.0));
}
template struct DeclaredSection<LinesSection>;

}  // namespace rollspec::study
