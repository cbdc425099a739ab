#pragma once
// Numbers as messages and tables print them.
// number_text: six significant digits ("%.6g"), nan and inf spelled out; four_digits: "%.4g";
// exact_text: "%.17g", every bit of a double (the input texts that cached tables hash).
#include <cstdio>
#include <string>

namespace rollspec::io {

inline std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

inline std::string four_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

inline std::string exact_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A count with its noun, singular for one: "1 realisation", "3 realisations" (nouns with a plain -s plural).
inline std::string counted(unsigned long long n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace rollspec::io
