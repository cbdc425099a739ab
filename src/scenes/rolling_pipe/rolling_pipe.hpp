#pragma once
// Scene `rolling-pipe` (issue 7; seed 000's beam model as a Monte-Carlo scene): a tube of
// geometrically exact beam elements lies across the rolling direction on a rigid rough surface
// and rolls over it under gravity. Per realisation: the surface (a line texture along the
// rolling direction, or an isotropic surface) drawn from the realisation's Philox streams, the
// rolling-contact dynamics of kernels/rolling (node spheres with Coulomb rolling friction and a
// normal damper on the height field, R-61..R-64), and Welch PSDs of the vertical acceleration at
// the sensor nodes. Same result layout as the ball-on-beam scenes (/psd/..., /bands/...).
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> rolling_pipe_keys();
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> rolling_pipe_first_keys();
std::unique_ptr<Scene> make_rolling_pipe(const study::KeyReader& s);
// The shape of its /psd and /bands, from its settings (a sweep checks it before any point runs).
ResultShape rolling_pipe_result_shape(const study::KeyReader& s);

// The relations of its dimensions (rolling_pipe_relations.cpp); its memory model and the references a run cites
// (rolling_pipe_row_parts.cpp).
std::vector<DimensionRelation> rolling_pipe_relations(const study::KeyReader& s);
std::vector<MemoryItem> rolling_pipe_memory(const study::KeyReader& s, int threads);
std::vector<std::string> rolling_pipe_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
