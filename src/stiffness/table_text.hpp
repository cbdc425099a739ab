#pragma once
// Text forms shared by the cached stage tables: numbers in round-trip precision (so a table's
// canonical inputs compare exactly), and the checksum over columns (io/content_hash.hpp).
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "src/io/content_hash.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::stiffness {

// A length in mm (from 1 mm) or um, three digits: grid sizes in plans and messages.
inline std::string um(double m) {
  return m >= 1e-3 ? io::three_digits(m * 1e3) + " mm" : io::three_digits(m * 1e6) + " um";
}

// The content hash of the columns' bytes, in order, continuing from `h`.
inline std::uint64_t column_hash(const std::vector<const std::vector<double>*>& columns,
                                 std::uint64_t h = io::kFnv1a64Start) {
  for (const auto* c : columns) h = io::fnv1a64(c->data(), c->size() * sizeof(double), h);
  return h;
}

}  // namespace rollspec::stiffness
