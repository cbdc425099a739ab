#include "src/study/sections/ensemble_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<EnsembleSection> EnsembleSection::declare() {
  using T = EnsembleSection;
  return SectionKeys<T>("ensemble")
      .integer("chunk_size", &T::chunk_size,
               "realisations per checkpointed chunk (a power of two; does not change the result)", "16", 1, 1 << 20)
      .power_of_two();
}
template struct DeclaredSection<EnsembleSection>;

}  // namespace rollspec::study
