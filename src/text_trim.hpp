#pragma once
// Text without its leading and trailing blanks: study lines, CSV cells, channel names.
#include <string>

namespace rollspec {

inline std::string trim(const std::string& s, const char* blanks = " \t\r") {
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

}  // namespace rollspec
