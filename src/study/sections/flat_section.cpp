#include "src/study/sections/flat_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<FlatSection> FlatSection::declare() {
  using T = FlatSection;
  return SectionKeys<T>("flat")
      .real("youngs_modulus", &T::youngs_modulus, "Pa", "flat's Young's modulus", "210e9", above(0.0))
      .real("poisson", &T::poisson, "-", "flat's Poisson's ratio", "0.3", {-1.0, 0.5, false, false});
}
template struct DeclaredSection<FlatSection>;

}  // namespace rollspec::study
