#pragma once
// Reading a choice key into its enum, through the table its section declares (key_spec.hpp's
// Choice). The study has already refused a value outside the table (exit 78, the allowed values
// listed); a value that still misses here is refused the same way rather than falling through.
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::study {

template <class E, std::size_t N>
E read_choice(const KeyReader& s, const std::string& full_key, const ChoiceTable<E, N>& table) {
  const std::string value = s.text(full_key);
  std::string allowed;
  for (const auto& c : table) {
    if (value == c.spelling) return c.value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(c.spelling);
  }
  s.refuse(full_key, "not a known choice; allowed: one of " + allowed);
}

}  // namespace rollspec::study
