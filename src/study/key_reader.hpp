#pragma once
// Reading a resolved study's keys: what the typed sections (src/study/sections/) need, and no more.
// A KeyReader holds the validated entries (value and origin of every key of the scene, defaults
// included); loading a file and --set overrides belongs to Study (study.hpp), which few files need.
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

class KeyReader {
 public:
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

 protected:
  std::string file_;
  std::string directory_;
  std::string scene_;
  std::vector<KeySpec> keys_;
  std::map<std::string, Entry> entries_;
};

}  // namespace rollspec::study
