#include "src/study/sections/lines_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<LinesSection>& declared() {
  using L = LinesSection;
  static const auto k =
      SectionKeys<L>("lines")
          .integer("count", &L::count, "line textures to generate", "10", 0, 1e6)
          .real("length", &L::length, "m", "length of each line texture", "0.4", above(0.0))
          .real("spacing", &L::spacing, "m", "sample spacing dx of the lines (dx <= pi / k_max)", "1e-5", above(0.0));
  return k;
}
}  // namespace

std::vector<KeySpec> LinesSection::keys() { return declared().keys(); }
LinesSection LinesSection::parse(const KeyReader& s) { return declared().read(s); }

}  // namespace rollspec::study
