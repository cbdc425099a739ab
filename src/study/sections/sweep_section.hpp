#pragma once
// [sweep] (any scene with an ensemble or a single run): which study keys take which values, one
// run per point. Its keys are other study keys ("ball.speed = 1, 2, 3") plus its own `mode`, so
// the section is taken out of the study text before the scene's key table checks the rest, and
// each swept key is checked against that table here. A point is the study with one more --set per
// swept key; each value is checked by the loader when the point's study is made.
#include <cstddef>
#include <string>
#include <vector>

#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

// One "section.key = v1, v2, ..." of [sweep] (or a --sweep), before the scene's table checks it.
struct SweepLine {
  std::string key, value;
  int line = 0;  // 0: --sweep on the command line
};

struct SweptKey {
  std::string key;                  // "ball.speed"
  std::string dimension;            // "ball_speed"
  std::string unit;                 // from the key's KeySpec
  std::vector<std::string> values;  // as written (the loader canonicalises each point's)
  KeyOrigin origin;
};

struct SweepSection {
  bool zipped = false;         // false: crossed (every combination)
  std::vector<SweptKey> keys;  // in [sweep] order, then --sweep order
  KeyOrigin mode_origin;

  bool empty() const { return keys.empty(); }
  // The number of points and the --set list of point `index` (crossed: the last key varies fastest).
  std::size_t points() const;
  std::vector<std::string> point_sets(std::size_t index) const;
  // The dimension lengths of the result's leading axes: one per key (crossed) or one (zipped).
  std::vector<std::size_t> shape() const;

  // `lines` from split_sweep (file), `cli` from --sweep section.key=v1,v2 (command line); `base` is
  // the study without [sweep], whose key table the swept keys must belong to.
  // The canonical text of swept key `key` in the study of a point (the value its axis shows).
  static std::string value_at(const KeyReader& point, const std::string& key);

  static SweepSection parse(const std::string& file, const std::vector<SweepLine>& lines,
                            const std::vector<std::string>& cli, const KeyReader& base);
};

// Takes the [sweep] section out of a study file's text: its lines become blank (so every other
// line keeps its number) and are returned.
std::vector<SweepLine> split_sweep(const std::string& file, std::string& text);

}  // namespace rollspec::study
