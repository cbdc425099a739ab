#pragma once
// A test-only scene, `white-noise`, in its own folder: one sensor reading stationary Gaussian white noise of a
// one-sided PSD level S ([noise] level) at the sample rate of [signal]. Its exact answer is S in every bin (a
// Welch estimate of white noise is unbiased with any window). It exists to show that a scene is its folder
// plus one registry row: linked into a test build of the command (rollspec_toy), `keys`, `init`, `plan`, `run`
// and the generated key reference pick it up with no other edit (tests/engine/test_toy_scene.py).
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {
struct NoiseSection : DeclaredSection<NoiseSection> {
  double level = 0.0;  // one-sided PSD, (m/s^2)^2/Hz
  static SectionKeys<NoiseSection> declare();
};
}  // namespace rollspec::study

namespace rollspec::scenes {

std::vector<study::KeySpec> white_noise_keys();
std::unique_ptr<Scene> make_white_noise(const study::KeyReader& s);
SceneInfo white_noise_row();

}  // namespace rollspec::scenes
