// fit's keys checked as a whole before the first run: the study with its --set, each --at point, and
// each --vary range against its key's type and range and at both of its ends, so that no later run
// refuses a value the user never wrote.
#include <cstdio>
#include <string>
#include <vector>

#include "src/fit/fit_model.hpp"
#include "src/run/run_phases.hpp"
#include "src/error.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/run_warning.hpp"

namespace rollspec::fit {

using run::make_scene;
using run::resolve_study;
using run::StudyArgs;

namespace {

using io::number_text;

const study::KeySpec* find_spec(const study::KeyReader& s, const std::string& key) {
  for (const auto& k : s.keys())
    if (k.full_name() == key) return &k;
  return nullptr;
}

bool inside(const study::KeySpec& k, double v) {
  const bool above = k.min_inclusive ? v >= k.min : v > k.min;
  const bool below = k.max_inclusive ? v <= k.max : v < k.max;
  return above && below;
}

// The study loaded with `sets`, a refusal prefixed by what the user wrote that led to it.
study::Study load_with(const FitInputs& in, const std::vector<std::string>& sets, const std::string& what) {
  StudyArgs a{in.study, in.sets, ""};
  a.sets.insert(a.sets.end(), sets.begin(), sets.end());
  try {
    study::Study s = resolve_study(a);
    make_scene<scenes::Scene>(s);  // the scene's own cross-key checks (a record against its segment)
    return s;
  } catch (const UserError& e) {
    throw UserError(e.exit_code(), what + ": " + e.what());
  }
}

void check_vary(const FitInputs& in, const study::KeyReader& base, const VaryRange& v) {
  const std::string where = "--vary " + v.key + "=" + number_text(v.lo) + ":" + number_text(v.hi);
  const study::KeySpec* k = find_spec(base, v.key);
  if (!k) {  // the loader names an unknown key and the keys of its section; the value as the runs set it
    load_with(in, {v.key + "=" + io::exact_text(v.lo)}, where);
    throw usage_error(where + ": " + v.key + " is not a key of scene " + base.scene());
  }
  if (k->type != study::KeyType::real)
    throw usage_error(where + ": " + v.key + " takes " + k->allowed() +
                      "; fit searches a continuous range, so it varies real-valued keys only");
  for (const double end : {v.lo, v.hi})
    if (!inside(*k, end))
      throw usage_error(where + ": " + number_text(end) + " lies outside the key's range; allowed: " + k->allowed());
}

}  // namespace

void check_fit_keys(const FitInputs& in) {
  // Only refusals are this check's; a warning at a range's end is the run's there, gathered with the others.
  const io::RunWarningCapture quiet;
  io::require_regular_input(in.study, "study file");
  const study::Study base = load_with(in, {}, in.study);
  for (const auto& v : in.vary) check_vary(in, base, v);
  std::vector<std::vector<std::string>> points;
  for (const auto& p : in.points) points.push_back(p.sets);
  if (points.empty()) points.emplace_back();
  // Each operating point, with every varied key at each end of its range: cross-key checks (a speed
  // against the record, a radius against the beam) refuse here, naming the option, not a later run.
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string at = in.points.size() > i && !in.points[i].at.empty() ? "--at " + clip(in.points[i].at) : "";
    if (!at.empty()) load_with(in, points[i], at);
    for (const auto& v : in.vary)
      for (const double end : {v.lo, v.hi}) {
        std::vector<std::string> sets = points[i];
        sets.push_back(v.key + "=" + io::exact_text(end));
        load_with(in, sets, (at.empty() ? "" : at + ", ") + "--vary " + v.key + " at " + number_text(end));
      }
  }
}

}  // namespace rollspec::fit
