#pragma once
// Scene `stiffness`: only the contact-stiffness stage — a smooth ball ([ball]) pressed onto a rough
// or smooth flat ([flat], [surface], [texture]) — built or reused by `rollspec stiffness`.
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> stiffness_scene_keys();
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> stiffness_first_keys();
std::unique_ptr<Scene> make_stiffness_scene(const study::KeyReader& s);

// The study's ball ([ball]: radius, E*, weight) on a body of Young's modulus `other_modulus` and
// Poisson's ratio `other_poisson`.
BallContact ball_contact_pair(const study::KeyReader& s, double other_modulus, double other_poisson);
// Scene stiffness's contact: the ball on the flat ([flat]).
BallContact stiffness_contact_pair(const study::KeyReader& s);

// Its memory model, the relations of its dimensions and the references a run cites (stiffness_row_parts.cpp).
std::vector<MemoryItem> stiffness_memory(const study::KeyReader& s, int threads);
std::vector<DimensionRelation> stiffness_relations(const study::KeyReader& s);
std::vector<std::string> stiffness_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
