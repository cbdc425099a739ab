#include "src/cli/study_template.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "src/cli/section_order.hpp"
#include "src/cli/study_template_keys.hpp"
#include "src/scenes/scene.hpp"
#include "src/version.hpp"

namespace rollspec::cli {

namespace {

using study::KeySpec;

// Comment text folded at about 96 columns, each line starting with `lead`.
std::string comment(const std::string& text, const std::string& lead) {
  std::istringstream words(text);
  std::string word, line, out;
  while (words >> word) {
    if (!line.empty() && lead.size() + line.size() + 1 + word.size() > 96) {
      out += lead + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += lead + line + "\n";
  return out;
}

// "a finite number > 0" without the " (m)" allowed() appends: the unit has its own place.
std::string allowed_without_unit(const KeySpec& k) {
  std::string a = k.allowed();
  const std::string suffix = " (" + k.unit + ")";
  if (k.unit != "-" && a.size() > suffix.size() && a.compare(a.size() - suffix.size(), suffix.size(), suffix) == 0)
    a.resize(a.size() - suffix.size());
  return a;
}

// What a key means, in which unit, what it allows and its default.
std::string describe(const KeySpec& k, const std::string& lead) {
  std::string text = k.doc;
  if (k.unit != "-") text += " [unit: " + k.unit + "]";
  text += ". Allowed: " + allowed_without_unit(k);
  // "default: X" stays on one line ('\x01' is a space the folding does not break at).
  text += k.default_value ? "; default:\x01" + (k.default_value->empty() ? std::string("empty") : *k.default_value)
                          : std::string("; required");
  std::string out = comment(text + ".", lead);
  std::replace(out.begin(), out.end(), '\x01', ' ');
  return out;
}

const KeySpec& spec_of(const std::vector<KeySpec>& keys, const std::string& full_name, const std::string& scene) {
  for (const auto& k : keys)
    if (k.full_name() == full_name) return k;
  // The first-key lists are checked against every scene's table by tests/cli/test_init_command.py.
  throw std::logic_error("rollspec init " + scene + ": first key " + full_name + " is not in the scene's key table");
}

std::string header(const std::string& scene) {
  std::ostringstream s;
  s << kStudyTemplateMarker << " (rollspec init " << scene << ", rollspec " << kVersion << ")\n";
  s << comment("A study of the " + scene + " scene: " + scenes::find_scene(scene).description + ".", "# ");
  s << "#\n"
    << comment(
           "The format: INI text, [section] headers and key = value lines; '#' starts a comment. Values are "
           "in SI units, named beside each key. First come the keys to set for your own rig, then every "
           "other key, commented out at its default: remove the leading '# ' to change one.",
           "# ")
    << "#\n";
  const std::string run = scenes::command_name(scenes::find_scene(scene).command);
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"rollspec keys " + scene, "every key: unit, allowed values, default"},
      {"rollspec plan FILE", "check the study, see what would run"},
      {"rollspec " + run + " FILE --out OUT.h5", "run it"},
      {"... --set section.key=value", "change a value for one run, e.g. --set study.realisations=5"},
  };
  for (const auto& [command, what] : commands)
    s << "#   " << command << std::string(command.size() < 36 ? 36 - command.size() : 1, ' ') << what << "\n";
  return s.str();
}

}  // namespace

std::string study_template(const std::string& scene) {
  const std::vector<KeySpec> table = scenes::schema_for(scene);
  std::vector<KeySpec> first;
  std::vector<std::string> values;
  for (const auto& f : first_keys(scene)) {
    const KeySpec& k = spec_of(table, f.full_name, scene);
    first.push_back(k);
    values.push_back(f.value ? *f.value : k.default_value.value_or(""));
  }
  // A required key the list leaves out still has to be set for the study to load.
  std::vector<KeySpec> rest;
  for (const auto& k : table) {
    const bool listed =
        std::any_of(first.begin(), first.end(), [&](const KeySpec& f) { return f.full_name() == k.full_name(); });
    if (listed) continue;
    if (!k.default_value)
      throw std::logic_error("rollspec init " + scene + ": required key " + k.full_name() +
                             " is not among the first keys");
    rest.push_back(k);
  }

  std::ostringstream s;
  s << header(scene);
  s << "\n# ==== The keys to set first ====\n";
  for (const auto& group : group_by_section(first)) {
    s << "\n[" << group.section << "]\n";
    for (const auto& k : group.keys) {
      const auto i = static_cast<std::size_t>(
          std::find_if(first.begin(), first.end(), [&](const KeySpec& f) { return f.full_name() == k.full_name(); }) -
          first.begin());
      s << describe(k, "# ") << k.key << " = " << values[i] << "\n";
    }
  }
  s << "\n# ==== Every other key, at its default (remove the leading '# ' to change one) ====\n";
  for (const auto& group : group_by_section(rest)) {
    s << "\n[" << group.section << "]\n";
    for (const auto& k : group.keys) s << describe(k, "#   ") << "# " << k.key << " = " << *k.default_value << "\n";
  }
  return s.str();
}

}  // namespace rollspec::cli
