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
#include <map>
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"

namespace rollspec::study {

struct Origin {
  std::string file;  // study file, or "command line"
  int line = 0;      // > 0: line in file; 0: documented default; -1: --set override
  std::string describe() const;
};

struct Entry {
  std::string value;  // canonical text of the value
  Origin origin;
};

// Returns the full key table (common keys + scene keys) for a scene name, or throws UserError
// naming the allowed scenes.
using SchemaLookup = std::function<std::vector<KeySpec>(const std::string& scene)>;

class Study {
 public:
  static Study load(const std::string& path, const std::vector<std::string>& overrides, const SchemaLookup& schema);
  // The same from study text already read (a checkpoint's resolved study): `path` names it in
  // messages and its directory resolves relative paths, as if the text were that file.
  static Study parse(const std::string& path, std::string text, const std::vector<std::string>& overrides,
                     const SchemaLookup& schema);

  const std::string& file() const { return file_; }
  const std::string& scene() const { return scene_; }
  bool has(const std::string& full_key) const;
  // Whether the study file or a --set override gave the key its value (false: the documented
  // default), so a stage can derive a value the study left open.
  bool is_set(const std::string& full_key) const;
  double real(const std::string& full_key) const;
  long long integer(const std::string& full_key) const;
  std::string text(const std::string& full_key) const;
  bool boolean(const std::string& full_key) const;
  std::string path(const std::string& full_key) const;  // usable from the current directory
  // A comma-separated text value as trimmed items (empty items dropped).
  std::vector<std::string> list(const std::string& full_key) const;
  // A comma-separated list of finite numbers; refuses a non-number, or a count other than
  // `expected` when it is > 0.
  std::vector<double> numbers(const std::string& full_key, std::size_t expected = 0) const;
  const Entry& entry(const std::string& full_key) const;
  const std::vector<KeySpec>& keys() const { return keys_; }

  // "file:line: [section] key = value" for messages of later, cross-key checks.
  std::string where(const std::string& full_key) const;
  // A UserError (exit 78) for a value that passed its own range check but not a cross-key check.
  [[noreturn]] void refuse(const std::string& full_key, const std::string& why) const;

  // Every key of the scene in table order, defaults included: "[section]\nkey = value\n...".
  std::string canonical_text() const;
  // The same without the listed keys (e.g. study.realisations for checkpoint hashes).
  std::string canonical_text_without(const std::vector<std::string>& excluded) const;
  // The --set overrides as "section.key=value" with canonical values (paths made absolute), so a
  // later run (--resume) can repeat them from another directory.
  std::vector<std::string> overrides() const;
  // Files the study reads: the study file and every path-valued key that is not "none".
  std::vector<std::string> input_files() const;

 private:
  std::string file_;
  std::string directory_;
  std::string scene_;
  std::vector<KeySpec> keys_;
  std::map<std::string, Entry> entries_;
};

}  // namespace rollspec::study
