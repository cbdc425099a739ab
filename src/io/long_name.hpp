#pragma once
// The CF `long_name` of a dataset: the label plots and xarray show beside its units. It is the
// dataset's description up to its first parenthesis or semicolon (the explanation after them is
// kept in `description` only).
#include <algorithm>
#include <string>

namespace rollspec::io {

inline std::string long_name_of(const std::string& description) {
  const std::size_t cut = std::min(description.find(" ("), description.find("; "));
  return cut == std::string::npos ? description : description.substr(0, cut);
}

}  // namespace rollspec::io
