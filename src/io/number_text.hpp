#pragma once
// A number as messages and tables print it: six significant digits ("%.6g"), nan and inf spelled out.
#include <cstdio>
#include <string>

namespace rollspec::io {

inline std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace rollspec::io
