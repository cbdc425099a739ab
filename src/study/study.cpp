#include "src/study/study.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "src/error.hpp"
#include "src/io/input_file.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/text_trim.hpp"

namespace fs = std::filesystem;

namespace rollspec::study {

namespace {

struct RawEntry {
  std::string full_key;
  std::string value;
  int line;
};

// The study's one INI parser: each "section.key = value" in file order with its line, the syntax
// checked line by line so a malformed line is reported with its number.
std::vector<RawEntry> scan_lines(const std::string& file, const std::string& text) {
  std::vector<RawEntry> out;
  std::istringstream in(text);
  std::string raw, section;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (raw.find('\0') != std::string::npos)
      throw config_error(file + ":" + std::to_string(line) + ": the study file holds binary data; expected INI text");
    std::string s = raw;
    const auto hash = s.find('#');
    if (hash != std::string::npos) s = s.substr(0, hash);
    s = trim(s);
    if (s.empty() || s[0] == ';') continue;
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3)
        throw config_error(file + ":" + std::to_string(line) + ": malformed section header '" + clip(trim(raw)) +
                           "'; expected [name]");
      section = trim(s.substr(1, s.size() - 2));
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw config_error(file + ":" + std::to_string(line) + ": cannot read '" + clip(trim(raw)) +
                         "'; expected [section] or key = value");
    const std::string key = trim(s.substr(0, eq));
    if (key.empty()) throw config_error(file + ":" + std::to_string(line) + ": a line '= value' has no key");
    if (section.empty())
      throw config_error(file + ":" + std::to_string(line) + ": key '" + clip(key) +
                         "' stands before any [section]; every key belongs to a section");
    out.push_back({section + "." + key, trim(s.substr(eq + 1)), line});
  }
  return out;
}

std::string format_real(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool is_power_of_two(long long v) { return v > 0 && (v & (v - 1)) == 0; }

// Validates one value against its key; returns the canonical text of the value.
std::string check_value(const KeySpec& spec, const std::string& value, const Origin& origin,
                        const std::string& directory) {
  const std::string head = origin.describe() + ": [" + spec.section + "] " + spec.key + " = " + clip(value) + ": ";
  const std::string allowed = "; allowed: " + spec.allowed();
  if (value.empty() && spec.type == KeyType::text) return value;
  if (value.empty())
    throw config_error(origin.describe() + ": [" + spec.section + "] " + spec.key + " has no value" + allowed);
  switch (spec.type) {
    case KeyType::real: {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0') throw config_error(head + "not a number" + allowed);
      // strtod also reads C's hexadecimal numbers (0x10 = 16): a study states its values in decimal.
      if (value.find_first_of("xX") != std::string::npos)
        throw config_error(head + "a hexadecimal number; write it in decimal" + allowed);
      if (std::isnan(v)) throw config_error(head + "NaN is not a value" + allowed);
      if (!std::isfinite(v)) throw config_error(head + "not finite (too large for a double, or Inf)" + allowed);
      const bool below = spec.min_inclusive ? v < spec.min : v <= spec.min;
      const bool above = spec.max_inclusive ? v > spec.max : v >= spec.max;
      if (below || above) throw config_error(head + "out of range" + allowed);
      return format_real(v);
    }
    case KeyType::integer: {
      long long v = 0;
      const char* b = value.c_str();
      const char* e = b + value.size();
      if (*b == '+') ++b;
      const auto r = std::from_chars(b, e, v);
      if (r.ec == std::errc::result_out_of_range) throw config_error(head + "too large a number" + allowed);
      if (r.ec != std::errc() || r.ptr != e) throw config_error(head + "not a whole number" + allowed);
      // Exactly, not through a double: 9000000000000000001 rounds to 9e18 and would pass a bound of 9e18.
      const auto d = static_cast<double>(v);
      const bool below = d < spec.min || (d == spec.min && v < static_cast<long long>(spec.min));
      const bool above = d > spec.max || (d == spec.max && v > static_cast<long long>(spec.max));
      if (below || above) throw config_error(head + "out of range" + allowed);
      if (spec.power_of_two && !is_power_of_two(v)) throw config_error(head + "not a power of two" + allowed);
      return std::to_string(v);
    }
    case KeyType::choice: {
      for (const auto& c : spec.choices)
        if (c == value) return value;
      throw config_error(head + "not a known choice" + allowed);
    }
    case KeyType::boolean: {
      if (value == "true" || value == "false") return value;
      throw config_error(head + "not a boolean" + allowed);
    }
    case KeyType::path: {
      if (value == "none") return value;
      const fs::path p = fs::path(value).is_absolute() ? fs::path(value) : fs::path(directory) / value;
      std::error_code ec;
      if (fs::is_directory(p, ec))
        throw missing_input(head + "is a directory, not a file (looked for " + p.string() + ")" + allowed);
      struct stat st {};
      if (::stat(p.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw missing_input(head + "is " + io::file_kind(st.st_mode) + ", not a regular file (looked for " +
                            p.string() + ")" + allowed);
      if (!fs::is_regular_file(p, ec))
        throw missing_input(head + "no such file (looked for " + p.string() + ")" + allowed);
      return value;
    }
    case KeyType::text:
      return value;
  }
  return value;
}

const KeySpec* find_spec(const std::vector<KeySpec>& keys, const std::string& full) {
  for (const auto& k : keys)
    if (k.full_name() == full) return &k;
  return nullptr;
}

std::string known_keys_of(const std::vector<KeySpec>& keys, const std::string& section) {
  std::string s;
  for (const auto& k : keys)
    if (k.section == section) s += (s.empty() ? "" : ", ") + k.key;
  return s;
}

std::string known_sections(const std::vector<KeySpec>& keys) {
  std::vector<std::string> seen;
  for (const auto& k : keys)
    if (std::find(seen.begin(), seen.end(), k.section) == seen.end()) seen.push_back(k.section);
  std::string s;
  for (const auto& n : seen) s += (s.empty() ? "[" : ", [") + n + "]";
  return s;
}

// Keys that were renamed: the error names the new key instead of listing all keys.
const char* retired_key_hint(const std::string& full) {
  if (full == "contact.patch_filter")
    return "was replaced by [contact] filter = none | patch | iso2d | solver (patch_filter = true is filter = patch, "
           "false is "
           "filter = none)";
  return nullptr;
}

void refuse_unknown(const std::vector<KeySpec>& keys, const std::string& full, const std::string& value,
                    const Origin& origin, const std::string& scene) {
  if (const char* hint = retired_key_hint(full))
    if (find_spec(keys, full.substr(0, full.find('.')) + ".filter"))
      throw config_error(origin.describe() + ": [contact] patch_filter = " + clip(value) + " " + hint);
  const auto dot = full.find('.');
  const std::string section = full.substr(0, dot), key = full.substr(dot + 1);
  const std::string known = known_keys_of(keys, section);
  if (known.empty())
    throw config_error(origin.describe() + ": unknown section [" + clip(section) + "] (key " + clip(key) + " = " +
                       clip(value) + ") for scene " + scene + "; allowed sections: " + known_sections(keys));
  throw config_error(origin.describe() + ": unknown key [" + section + "] " + clip(key) + " = " + clip(value) +
                     " for scene " + scene + "; allowed keys in [" + section + "]: " + known);
}

}  // namespace

Study Study::load(const std::string& path, const std::vector<std::string>& overrides, const SchemaLookup& schema) {
  std::error_code dir_ec;
  if (fs::is_directory(path, dir_ec))
    throw missing_input("cannot read study file '" + path + "': it is a directory; expected an INI file");
  io::require_regular_input(path, "study file");
  // A study is a few kilobytes of keys: a huge file is a wrong argument, refused before it is read.
  constexpr std::uintmax_t kLargestStudy = 4u << 20;
  std::error_code size_ec;
  const std::uintmax_t bytes = fs::file_size(path, size_ec);
  if (!size_ec && bytes > kLargestStudy)
    throw config_error("study file '" + path + "' is " + std::to_string(bytes) + " bytes; allowed: at most " +
                       std::to_string(kLargestStudy) +
                       " bytes (a study is an INI file of keys; is this the right file?)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw missing_input("cannot open study file '" + path + "'");
  std::ostringstream buf;
  buf << in.rdbuf();
  return parse(path, buf.str(), overrides, schema);
}

Study Study::parse(const std::string& path, std::string text, const std::vector<std::string>& overrides,
                   const SchemaLookup& schema) {
  // A UTF-8 byte-order mark (editors on Windows) is not part of the first section header.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  if (text.empty())
    throw config_error(path + ": the study file is empty; it needs at least [study] scene, realisations and seed");

  const std::vector<RawEntry> lines = scan_lines(path, text);
  Study s;
  s.file_ = path;
  s.directory_ = fs::path(path).parent_path().string();

  // Duplicates are refused: the last-one-wins rule hides mistakes.
  std::map<std::string, int> first_line;
  for (const auto& e : lines) {
    const auto it = first_line.find(e.full_key);
    if (it != first_line.end()) {
      const auto dot = e.full_key.find('.');
      throw config_error(path + ":" + std::to_string(e.line) + ": duplicated key [" + clip(e.full_key.substr(0, dot)) +
                         "] " + clip(e.full_key.substr(dot + 1)) + " = " + clip(e.value) + " (first set at line " +
                         std::to_string(it->second) + "); each key may appear once");
    }
    first_line[e.full_key] = e.line;
  }

  // Overrides: "section.key=value".
  struct Override {
    std::string full_key, value;
  };
  std::vector<Override> sets;
  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    const auto dot = o.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq)
      throw usage_error("--set " + clip(o) + ": expected section.key=value, e.g. --set study.realisations=100");
    // A line break would inject lines into the resolved study stored in every output.
    for (const char ch : o)
      if ((static_cast<unsigned char>(ch) < 0x20 && ch != '\t') || ch == 0x7f)
        throw usage_error("--set " + clip(o) + ": holds a line break or control character (byte " +
                          std::to_string(static_cast<unsigned char>(ch)) + "); allowed: one line of text");
    sets.push_back({trim(o.substr(0, eq)), trim(o.substr(eq + 1))});
  }

  // The scene decides which keys exist.
  std::string scene;
  Origin scene_origin{path, 0};
  const std::string scene_key = StudySection::key(&StudySection::scene);
  for (const auto& e : lines)
    if (e.full_key == scene_key) scene = e.value, scene_origin = Origin{path, e.line};
  for (const auto& o : sets)
    if (o.full_key == scene_key) scene = o.value, scene_origin = Origin{"command line", -1};
  if (scene.empty()) throw config_error(path + ": missing required key [study] scene; every study names its scene");
  try {
    s.keys_ = schema(scene);
  } catch (const UserError& e) {
    throw UserError(e.exit_code(), scene_origin.describe() + ": " + e.what());
  }
  s.scene_ = scene;

  for (const auto& e : lines) {
    const Origin origin{path, e.line};
    const KeySpec* spec = find_spec(s.keys_, e.full_key);
    if (!spec) refuse_unknown(s.keys_, e.full_key, e.value, origin, scene);
    s.entries_[e.full_key] = {check_value(*spec, e.value, origin, s.directory_), origin};
  }
  for (const auto& o : sets) {
    const Origin origin{"command line", -1};
    const KeySpec* spec = find_spec(s.keys_, o.full_key);
    if (!spec) refuse_unknown(s.keys_, o.full_key, o.value, origin, scene);
    s.entries_[o.full_key] = {check_value(*spec, o.value, origin, fs::current_path().string()), origin};
    if (spec->type == KeyType::path && !fs::path(o.value).is_absolute())
      s.entries_[o.full_key].value = fs::absolute(o.value).string();
  }
  for (const auto& k : s.keys_) {
    if (s.entries_.count(k.full_name())) continue;
    if (!k.default_value)
      throw config_error(path + ": missing required key [" + k.section + "] " + k.key + " (" + k.doc +
                         "); allowed: " + k.allowed());
    s.entries_[k.full_name()] = {check_value(k, *k.default_value, Origin{path, 0}, s.directory_), Origin{path, 0}};
  }
  // The resolved study is stored as one HDF5 attribute in every output, and an attribute holds at
  // most 64 KiB: refuse a longer study now, naming its longest value, not at the final write.
  constexpr std::size_t kMaxStudyText = 60 * 1024;
  const std::size_t size = s.canonical_text().size();
  if (size > kMaxStudyText) {
    std::string longest;
    for (const auto& [key, e] : s.entries_)
      if (longest.empty() || e.value.size() > s.entries_.at(longest).value.size()) longest = key;
    s.refuse(longest, "makes the resolved study " + std::to_string(size) +
                          " bytes long (this value: " + std::to_string(s.entries_.at(longest).value.size()) +
                          " bytes); allowed: a study of at most " + std::to_string(kMaxStudyText) +
                          " bytes, which every output file stores");
  }
  return s;
}

}  // namespace rollspec::study
