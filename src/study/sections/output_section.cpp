#include "src/study/sections/output_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
const SectionKeys<OutputSection>& declared() {
  using O = OutputSection;
  static const auto k =
      SectionKeys<O>("output")
          .integer("time_histories", &O::time_histories, "store time histories of realisations 0..n-1", "0", 0, 1000)
          .boolean("reference", &O::reference,
                   "linearised law: also write the frequency-domain reference (/reference: expected Welch PSD and the "
                   "range that holds the ensemble mean), computed once after the ensemble",
                   "true");
  return k;
}
}  // namespace

std::vector<KeySpec> OutputSection::keys() { return declared().keys(); }
OutputSection OutputSection::parse(const KeyReader& s) { return declared().read(s); }

}  // namespace rollspec::study
