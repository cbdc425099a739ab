#pragma once
// Scene `texture`: only the roughness stages (line textures [lines], isotropic surfaces [surface])
// of a PSD ([texture]); `rollspec texture` writes them, `rollspec plan` shows them.
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> texture_scene_keys();
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> texture_first_keys();
std::unique_ptr<Scene> make_texture_scene(const study::KeyReader& s);

// Its memory model, the relations of its dimensions and the references a run cites (texture_row_parts.cpp).
std::vector<MemoryItem> texture_memory(const study::KeyReader& s, int threads);
std::vector<DimensionRelation> texture_relations(const study::KeyReader& s);
std::vector<std::string> texture_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
