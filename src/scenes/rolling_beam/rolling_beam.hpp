#pragma once
// Scene `rolling-beam` (design §6; seed 000): a geometrically exact beam (or a rigid disc) rolling
// and sliding on a rigid plane, each contact node a sphere of the section's radius with the rolling
// correction of the tangential gap (D-13, D-14), Coulomb stick/slip, friction moment. One
// deterministic run (quasi-static load stepping or Newmark dynamics, kernels/rolling); the result
// file holds the time histories under /time_history/.
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> rolling_beam_keys();
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> rolling_beam_first_keys();
std::unique_ptr<Scene> make_rolling_beam(const study::KeyReader& s);

// The relations of its dimensions (rolling_beam_relations.cpp); its memory model and the references a run cites
// (rolling_beam_row_parts.cpp).
std::vector<DimensionRelation> rolling_beam_relations(const study::KeyReader& s);
std::vector<MemoryItem> rolling_beam_memory(const study::KeyReader& s, int threads);
std::vector<std::string> rolling_beam_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
