#pragma once
// The keys a new study of each scene sets first (rollspec init writes them uncommented, at the
// top), with the value the template gives them. Unit, meaning, range and default come from the
// scene's key table; only the choice of keys and a few starting values live here.
#include <optional>
#include <string>
#include <vector>

namespace rollspec::cli {

struct FirstKey {
  std::string full_name;             // "section.key"
  std::optional<std::string> value;  // nullopt: the table's default
};

// The first keys of `scene` in the order the template lists them ([study] keys first).
std::vector<FirstKey> first_keys(const std::string& scene);

}  // namespace rollspec::cli
