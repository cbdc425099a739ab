#pragma once
// Text forms shared by the cached stage tables: hashes as 16 hex digits, numbers in round-trip
// precision (so a table's canonical inputs compare exactly), and the FNV-1a checksum over columns.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "src/ensemble/checkpoint.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::stiffness {

inline std::string hex16(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// A length in mm (from 1 mm) or um, three digits: grid sizes in plans and messages.
inline std::string um(double m) {
  char buf[32];
  if (m >= 1e-3)
    std::snprintf(buf, sizeof buf, "%.3g mm", m * 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.3g um", m * 1e6);
  return buf;
}

// FNV-1a over the bytes of the columns, in order, continuing from `h`.
inline std::uint64_t column_hash(const std::vector<const std::vector<double>*>& columns,
                                 std::uint64_t h = 14695981039346656037ull) {
  for (const auto* c : columns) h = ensemble::fnv1a64(c->data(), c->size() * sizeof(double), h);
  return h;
}

}  // namespace rollspec::stiffness
