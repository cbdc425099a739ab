#pragma once
// The theory-note equations (io/references.hpp ids) a verdict of `rollspec compare` used, from what it
// computed: the measurement and its floor, the bands, the prediction interval, the combined test and
// the level offset.
#include <string>
#include <vector>

#include "src/compare/band_verdict.hpp"

namespace rollspec::compare {

// `recordings`: the measurement was recordings put through the model's Welch estimator (not a PSD table);
// `predict`: the prediction intervals were given (M known and enough realisations).
std::vector<std::string> verdict_references(const Verdict& v, bool recordings, bool predict);

}  // namespace rollspec::compare
