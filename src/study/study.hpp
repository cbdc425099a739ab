#pragma once
// A study: the resolved, validated contents of a study file (INI: [section] + key = value) plus
// command-line overrides (--set section.key=value) plus documented defaults.
//
// Loading reads the file with one INI parser (file order, line numbers), then checks every entry against the
// scene's key table (key_spec.hpp) before any work starts: unknown sections and keys,
// duplicated keys, empty values, NaN/Inf, numbers that are not numbers, out-of-range values,
// unknown choices and missing files are refused with a UserError that names the file, line,
// key, value and what is allowed (exit 78, or 66 for a missing file).
#include <functional>
#include <string>
#include <vector>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

// Returns the full key table (common keys + scene keys) for a scene name, or throws UserError
// naming the allowed scenes.
using SchemaLookup = std::function<std::vector<KeySpec>(const std::string& scene)>;

class Study : public KeyReader {
 public:
  static Study load(const std::string& path, const std::vector<std::string>& overrides, const SchemaLookup& schema);
  // The same from study text already read (a checkpoint's resolved study): `path` names it in
  // messages and its directory resolves relative paths, as if the text were that file.
  static Study parse(const std::string& path, std::string text, const std::vector<std::string>& overrides,
                     const SchemaLookup& schema);
};

}  // namespace rollspec::study
