#pragma once
// Scene `stiffness`: only the contact-stiffness stage — a smooth ball ([ball]) pressed onto a rough
// or smooth flat ([flat], [surface], [texture]) — built or reused by `rollspec stiffness`.
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> stiffness_scene_keys();
std::unique_ptr<Scene> make_stiffness_scene(const study::KeyReader& s);

// Ball radius, effective modulus and weight of a stiffness or ball-on-beam study.
struct ContactPair {
  double radius, effective_modulus, weight;
};
ContactPair study_contact_pair(const study::KeyReader& s);

}  // namespace rollspec::scenes
