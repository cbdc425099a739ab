#include "src/study/sections/sweep_section.hpp"

#include <sstream>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/text_trim.hpp"

namespace rollspec::study {

namespace {

// "v1, v2, ..." strictly: an empty item (",," or a comma at either end) is a slip, not a value to drop.
std::vector<std::string> split_values(const std::string& text, const std::string& where, const KeySpec& spec) {
  std::vector<std::string> out;
  if (trim(text).empty()) throw config_error(where + ": no values; allowed: v1, v2, ... (" + spec.allowed() + ")");
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (item.empty())
      throw config_error(where + ": item " + std::to_string(out.size() + 1) +
                         " is empty; allowed: v1, v2, ... with a value between every two commas (" + spec.allowed() +
                         ")");
    out.push_back(item);
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::string where_of(const std::string& file, const SweepLine& l) {
  return (l.line > 0 ? file + ":" + std::to_string(l.line) : std::string("command line")) + ": [sweep] " + l.key +
         " = " + clip(l.value);
}

std::string section_keys(const KeyReader& base, const std::string& section) {
  std::string s;
  for (const auto& k : base.keys())
    if (k.section == section) s += (s.empty() ? "" : ", ") + k.key;
  return s;
}

SweptKey swept_key(const std::string& file, const SweepLine& l, const KeyReader& base) {
  const std::string where = where_of(file, l);
  const auto dot = l.key.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == l.key.size())
    throw config_error(where +
                       ": unknown key; allowed in [sweep]: mode, or section.key = v1, v2, ... naming a key "
                       "of the study");
  const std::string section = l.key.substr(0, dot);
  const KeySpec* spec = nullptr;
  for (const auto& k : base.keys())
    if (k.full_name() == l.key) spec = &k;
  if (!spec) {
    const std::string known = section_keys(base, section);
    throw config_error(where + ": unknown key " + clip(l.key) + " for scene " + base.scene() + "; allowed: " +
                       (known.empty() ? "a key of a section of the scene (rollspec keys " + base.scene() + ")"
                                      : "keys of [" + section + "]: " + known));
  }
  if (section == "study" && (spec->key == "scene" || spec->key == "seed"))
    throw config_error(where +
                       ": cannot be swept; every point runs the same scene with the same seed (common random "
                       "numbers)");
  SweptKey k{l.key, l.key, spec->unit, split_values(l.value, where, *spec), {where}};
  k.dimension[dot] = '_';
  return k;
}

}  // namespace

std::vector<SweepLine> split_sweep(const std::string& file, std::string& text) {
  std::vector<SweepLine> out;
  std::istringstream in(text);
  std::string raw, kept, section;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    std::string s = raw.substr(0, raw.find('#'));
    s = trim(s);
    if (!s.empty() && s.front() == '[' && s.back() == ']') section = trim(s.substr(1, s.size() - 2));
    if (section != "sweep") {
      kept += raw + "\n";
      continue;
    }
    kept += "\n";
    const auto eq = s.find('=');
    if (s.empty() || s[0] == ';' || s[0] == '[' || eq == std::string::npos) {
      if (!s.empty() && s[0] != ';' && s[0] != '[')
        throw config_error(file + ":" + std::to_string(line) + ": cannot read '" + clip(s) +
                           "' in [sweep]; expected section.key = v1, v2, ...");
      continue;
    }
    out.push_back({trim(s.substr(0, eq)), trim(s.substr(eq + 1)), line});
  }
  text = kept;
  return out;
}

SweepSection SweepSection::parse(const std::string& file, const std::vector<SweepLine>& lines,
                                 const std::vector<std::string>& cli, const KeyReader& base) {
  SweepSection t;
  std::vector<SweepLine> all;
  for (const auto& l : lines) {
    if (l.key != "mode") {
      all.push_back(l);
      continue;
    }
    t.mode_origin = {where_of(file, l)};
    if (l.value != "crossed" && l.value != "zipped")
      t.mode_origin.refuse("not a known choice; allowed: one of crossed, zipped");
    t.zipped = l.value == "zipped";
  }
  for (const auto& c : cli) {
    const auto eq = c.find('=');
    if (eq == std::string::npos)
      throw usage_error("--sweep " + clip(c) + ": expected section.key=v1,v2,..., e.g. --sweep ball.speed=1,2,3");
    all.push_back({trim(c.substr(0, eq)), trim(c.substr(eq + 1)), 0});
  }
  for (const auto& l : all) {
    for (const auto& k : t.keys)
      if (k.key == l.key) throw config_error(where_of(file, l) + ": swept twice (first: " + k.origin.where + ")");
    t.keys.push_back(swept_key(file, l, base));
  }
  if (t.zipped)
    for (const auto& k : t.keys)
      if (k.values.size() != t.keys.front().values.size())
        throw config_error(k.origin.where + ": mode = zipped needs lists of equal length; " + t.keys.front().key +
                           " has " + std::to_string(t.keys.front().values.size()) + " values, " + k.key + " has " +
                           std::to_string(k.values.size()));
  return t;
}

std::string SweepSection::value_at(const KeyReader& point, const std::string& key) { return point.entry(key).value; }

std::size_t SweepSection::points() const {
  if (keys.empty()) return 0;
  if (zipped) return keys.front().values.size();
  std::size_t n = 1;
  for (const auto& k : keys) n *= k.values.size();
  return n;
}

std::vector<std::size_t> SweepSection::shape() const {
  if (zipped) return {keys.front().values.size()};
  std::vector<std::size_t> s;
  for (const auto& k : keys) s.push_back(k.values.size());
  return s;
}

std::vector<std::string> SweepSection::point_sets(std::size_t index) const {
  std::vector<std::string> sets(keys.size());
  for (std::size_t j = keys.size(); j-- > 0;) {
    const auto& v = keys[j].values;
    const std::size_t i = zipped ? index : index % v.size();
    sets[j] = keys[j].key + "=" + v[i];
    if (!zipped) index /= v.size();
  }
  return sets;
}

}  // namespace rollspec::study
