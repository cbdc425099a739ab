#include "src/scenes/dimension_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "src/scenes/scene.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::scenes {

namespace {

// Decades between a key's value and its documented default: where two written keys fail the same
// relations, the one further from the usual is the slip. A key whose default is 0 (derived from the
// others unless written) counts as far off: written, it is the one the user chose to state.
double decades_from_default(const study::KeyReader& s, const std::string& key) {
  for (const auto& k : s.keys()) {
    if (k.full_name() != key || !k.default_value) continue;
    const double d = std::strtod(k.default_value->c_str(), nullptr), v = s.real(key);
    if (d == 0.0) return 5.0;
    return d > 0.0 && v > 0.0 ? std::fabs(std::log10(v / d)) : 0.0;
  }
  return 0.0;
}

bool is_number_key(const study::KeyReader& s, const std::string& key) {
  for (const auto& k : s.keys())
    if (k.full_name() == key) return k.type == study::KeyType::real || k.type == study::KeyType::integer;
  return false;
}

}  // namespace

void refuse_failed_relations(const study::KeyReader& s, const std::vector<DimensionRelation>& relations) {
  std::map<std::string, int> failed_in;  // written keys: the relations each fails
  const DimensionRelation* first = nullptr;
  std::vector<DimensionRelation> failed;  // of the relations with a key the user wrote: defaults alone are
  for (const auto& r : relations) {       // no slip (an unused stage's defaults need not suit the study)
    if (r.holds) continue;
    bool written = false;
    for (const auto& k : r.keys)
      if (s.has(k) && s.is_set(k)) ++failed_in[k], written = true;
    if (written) failed.push_back(r);
  }
  if (failed.empty()) return;
  first = &failed.front();
  // The culprit: a written key of the most failed relations, then the furthest from its default
  // (in decades), then the first named (a relation lists its likelier culprit first).
  std::string culprit;
  double score = -1.0;
  for (const auto& r : failed) {
    for (const auto& k : r.keys) {
      if (!failed_in.count(k)) continue;
      const double v = failed_in[k] * 1000.0 + (is_number_key(s, k) ? decades_from_default(s, k) : 0.0);
      if (v > score + 1e-9) culprit = k, score = v;
    }
  }
  const DimensionRelation* shown = first;
  int more = 0;
  for (const auto& r : failed)
    if (std::find(r.keys.begin(), r.keys.end(), culprit) != r.keys.end()) {
      if (shown == first && std::find(first->keys.begin(), first->keys.end(), culprit) == first->keys.end()) shown = &r;
      ++more;
    }
  std::string others;
  for (const auto& k : shown->keys)
    if (k != culprit && s.has(k)) others += (others.empty() ? "" : ", ") + s.where(k);
  s.refuse(culprit, shown->why + (others.empty() ? "" : " (against " + others + ")") +
                        (more > 1 ? "; " + std::to_string(more - 1) + " more relation(s) of this key fail too" : "") +
                        "; lengths are in m and speeds in m/s: a value written in mm or um is 10^3 or 10^6 too large");
}

void check_dimensions(const study::KeyReader& s) {
  if (const auto& relations = find_scene(s.scene()).relations) refuse_failed_relations(s, relations(s));
}

}  // namespace rollspec::scenes
