#include "src/study/key_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "src/error.hpp"
#include "src/text_trim.hpp"

namespace fs = std::filesystem;

namespace rollspec::study {

std::string Origin::describe() const {
  if (line > 0) return file + ":" + std::to_string(line);
  if (line < 0) return "command line (--set)";
  return file + " (default)";
}

bool KeyReader::has(const std::string& full_key) const { return entries_.count(full_key) > 0; }

bool KeyReader::is_set(const std::string& full_key) const { return entry(full_key).origin.line != 0; }

const Entry& KeyReader::entry(const std::string& full_key) const {
  const auto it = entries_.find(full_key);
  if (it == entries_.end()) throw std::logic_error("study key not in the scene's table: " + full_key);
  return it->second;
}

double KeyReader::real(const std::string& k) const { return std::strtod(entry(k).value.c_str(), nullptr); }
long long KeyReader::integer(const std::string& k) const { return std::stoll(entry(k).value); }
std::string KeyReader::text(const std::string& k) const { return entry(k).value; }
bool KeyReader::boolean(const std::string& k) const { return entry(k).value == "true"; }

std::string KeyReader::path(const std::string& k) const {
  const Entry& e = entry(k);
  const fs::path p(e.value);
  if (e.value == "none" || p.is_absolute() || e.origin.line < 0) return p.string();
  return (fs::path(directory_) / p).string();
}

std::vector<std::string> KeyReader::list(const std::string& k) const {
  std::vector<std::string> out;
  std::istringstream in(entry(k).value);
  std::string item;
  while (std::getline(in, item, ',')) {
    item = trim(item);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::vector<double> KeyReader::numbers(const std::string& k, std::size_t expected) const {
  std::vector<double> out;
  for (const auto& item : list(k)) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !std::isfinite(v))
      refuse(k, "'" + clip(item) + "' is not a finite number; allowed: comma-separated numbers");
    out.push_back(v);
  }
  if (expected && out.size() != expected)
    refuse(k,
           "has " + std::to_string(out.size()) + " numbers; allowed: " + std::to_string(expected) + " comma-separated");
  return out;
}

std::string KeyReader::where(const std::string& k) const {
  const Entry& e = entry(k);
  const auto dot = k.find('.');
  return e.origin.describe() + ": [" + k.substr(0, dot) + "] " + k.substr(dot + 1) + " = " + clip(e.value);
}

void KeyReader::refuse(const std::string& k, const std::string& why) const {
  throw config_error(where(k) + ": " + why);
}

std::string KeyReader::canonical_text_without(const std::vector<std::string>& excluded) const {
  // Sections in the order they first appear, each once with all its keys: valid INI for any reader
  // (Python's configparser refuses a repeated section), though a scene adds keys to a common section.
  std::vector<std::string> sections;
  for (const auto& k : keys_)
    if (std::find(sections.begin(), sections.end(), k.section) == sections.end()) sections.push_back(k.section);
  std::ostringstream s;
  for (const auto& section : sections) {
    bool header = false;
    for (const auto& k : keys_) {
      if (k.section != section || std::find(excluded.begin(), excluded.end(), k.full_name()) != excluded.end())
        continue;
      if (!header) s << (s.tellp() > 0 ? "\n" : "") << "[" << section << "]\n";
      header = true;
      s << k.key << " = " << entry(k.full_name()).value << "\n";
    }
  }
  return s.str();
}

std::string KeyReader::canonical_text() const { return canonical_text_without({}); }

std::vector<std::string> KeyReader::overrides() const {
  std::vector<std::string> out;
  for (const auto& k : keys_) {
    const Entry& e = entry(k.full_name());
    if (e.origin.line < 0) out.push_back(k.full_name() + "=" + e.value);
  }
  return out;
}

std::vector<std::string> KeyReader::input_files() const {
  std::vector<std::string> out = {file_};
  for (const auto& k : keys_)
    if (k.type == KeyType::path && entry(k.full_name()).value != "none") out.push_back(path(k.full_name()));
  return out;
}

}  // namespace rollspec::study
