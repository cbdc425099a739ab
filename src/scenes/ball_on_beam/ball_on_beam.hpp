#pragma once
// Scene `ball-on-beam` (design §5; seeds 001 and 002): a smooth rigid ball rolls at constant speed
// over a rough modal Euler-Bernoulli beam. Per realisation: a line texture of the beam's surface
// from [texture] (Philox streams roughness_*), the ball-on-beam integration of kernels/beam
// (exact-step default, Dormand-Prince reference), Welch PSDs of the sensor accelerations, the
// contact force and the ball acceleration over the traverse, and the share of time in loss of
// contact. Averaged over realisations (and over sensors as seed 002 does).
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::beam {
class ModalBeam;
}

namespace rollspec::scenes {

std::vector<study::KeySpec> ball_on_beam_keys();
std::unique_ptr<Scene> make_ball_on_beam(const study::KeyReader& s);
// The shape of its /psd and /bands, from its settings (a sweep checks it before any point runs).
ResultShape ball_on_beam_result_shape(const study::KeyReader& s);

// The modal beam a study describes (for `rollspec modes`).
beam::ModalBeam study_modal_beam(const study::KeyReader& s);
// The ball on the beam (for `rollspec stiffness`: the table the scene's table law uses).
BallContact ball_on_beam_contact_pair(const study::KeyReader& s);
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> ball_on_beam_first_keys();

// Its memory model (ball_on_beam_memory.cpp) and the relations of its dimensions (ball_on_beam_dimensions.cpp).
std::vector<MemoryItem> ball_on_beam_memory(const study::KeyReader& s, int threads);
std::vector<DimensionRelation> ball_on_beam_relations(const study::KeyReader& s);
// The references a run cites (ball_on_beam_references.cpp).
std::vector<std::string> ball_on_beam_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
