#pragma once
// The documented keys of a study: type, unit, allowed range, default and meaning of each.
// Validation, the resolved-study echo and `rollspec keys` all read this one table.
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rollspec::study {

enum class KeyType { real, integer, text, choice, path, boolean };

struct KeySpec {
  std::string section;
  std::string key;
  KeyType type = KeyType::real;
  std::string unit = "-";                    // SI unit of the value, "-" for none
  std::string doc;                           // one line: what the key means
  std::optional<std::string> default_value;  // nullopt: the key is required
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  bool max_inclusive = true;
  std::vector<std::string> choices;  // for KeyType::choice
  bool power_of_two = false;         // for KeyType::integer

  std::string full_name() const { return section + "." + key; }
  std::string allowed() const;  // human text: "a number > 0 (Hz)", "one of hann, rectangular", ...
};

// Builders that keep scene schemas short and readable.
KeySpec real_key(std::string section, std::string key, std::string unit, std::string doc,
                 std::optional<std::string> default_value, double min, double max, bool min_inclusive = true,
                 bool max_inclusive = true);
KeySpec integer_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                    double min, double max);
KeySpec choice_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                   std::vector<std::string> choices);
KeySpec text_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);
KeySpec path_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);
KeySpec bool_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);

}  // namespace rollspec::study
