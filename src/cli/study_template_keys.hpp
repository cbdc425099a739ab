#pragma once
// The keys a new study of each scene sets first (rollspec init writes them uncommented, at the
// top), with the value the template gives them: [study]'s, then the scene's registry row's
// `first_keys`. Unit, meaning, range and default come from the scene's key table; only the choice
// of keys and a few starting values live in the row.
#include <string>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::cli {

using FirstKey = scenes::FirstKey;

// The first keys of `scene` in the order the template lists them ([study] keys first).
std::vector<FirstKey> first_keys(const std::string& scene);

}  // namespace rollspec::cli
