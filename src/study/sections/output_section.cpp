#include "src/study/sections/output_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<OutputSection> OutputSection::declare() {
  using O = OutputSection;
  return SectionKeys<O>("output")
      .integer("time_histories", &O::time_histories, "store time histories of realisations 0..n-1", "0", 0, 1000)
      .boolean("reference", &O::reference,
               "linearised law: also write the frequency-domain reference (/reference: expected Welch PSD and the "
               "range that holds the ensemble mean), computed once after the ensemble",
               "true");
}
template struct DeclaredSection<OutputSection>;

}  // namespace rollspec::study
