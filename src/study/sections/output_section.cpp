#include "src/study/sections/output_section.hpp"

#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> OutputSection::keys() {
  return {
      integer_key("output", "time_histories", "store time histories of realisations 0..n-1", std::string("0"), 0, 1000),
      bool_key("output", "reference",
               "linearised law: also write the frequency-domain reference (/reference: expected Welch PSD and the "
               "range that holds the ensemble mean), computed once after the ensemble",
               std::string("true")),
  };
}

OutputSection OutputSection::parse(const KeyReader& s) {
  OutputSection p;
  p.time_histories = s.integer("output.time_histories");
  p.reference = s.boolean("output.reference");
  return p;
}

}  // namespace rollspec::study
