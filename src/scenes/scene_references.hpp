#pragma once
// The papers and theory-note equations (io/references.hpp) a study's run uses, per scene, from the
// study's parsed choices: a row of the scene registry (SceneInfo::references) names its function here.
#include <string>
#include <vector>

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

std::vector<std::string> random_oscillator_references(const study::KeyReader& s);
std::vector<std::string> ball_on_beam_references(const study::KeyReader& s);
std::vector<std::string> rolling_beam_references(const study::KeyReader& s);
std::vector<std::string> rolling_pipe_references(const study::KeyReader& s);
std::vector<std::string> stiffness_references(const study::KeyReader& s);
std::vector<std::string> texture_references(const study::KeyReader& s);
// `rollspec texture` with --count: `surfaces` isotropic surfaces, whatever [surface] count says.
std::vector<std::string> texture_surface_references(const study::KeyReader& s, long long surfaces);

// The references of `s`'s scene (its registry row's function).
std::vector<std::string> study_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
