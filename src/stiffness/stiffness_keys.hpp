#pragma once
// Study keys of the stiffness-table stage ([stiffness]).
#include <vector>

#include "src/study/key_spec.hpp"

namespace rollspec::stiffness {

std::vector<study::KeySpec> stiffness_keys();

}  // namespace rollspec::stiffness
