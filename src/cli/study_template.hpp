#pragma once
// The text `rollspec init SCENE` writes: a commented study of the scene that loads, plans and runs
// as it stands. First the keys to set first (study_template_keys.hpp) with their meaning, unit,
// allowed values and default from the key table; then every other key, commented out at its
// default.
#include <string>

namespace rollspec::cli {

// The first line of every template: tells a file rollspec init wrote from a user's own.
constexpr const char* kStudyTemplateMarker = "# rollspec-study-template";

// `scene` must be a registered scene (scenes::find_scene).
std::string study_template(const std::string& scene);

}  // namespace rollspec::cli
