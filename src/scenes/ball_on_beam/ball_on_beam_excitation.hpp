#pragma once
// What drives the beam in one realisation of scene ball-on-beam, one kind per contact model:
// a synthesised line texture (Philox streams roughness_*), the linear spring's blocked force on that
// line (D-11), the contact solver's blocked force synthesised from its table's PSD (streams
// blocked_force_*), the strip's h_eq (line = strip) or nothing (law = path: the strip is in the law).
// Each kind owns its random streams and one workspace per ensemble thread; fill() is deterministic
// in the realisation id, whichever thread runs it.
#include <cstdint>
#include <memory>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/texture/line_texture.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_contact.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"

namespace rollspec::scenes {

class BallOnBeamExcitation {
 public:
  virtual ~BallOnBeamExcitation() = default;
  // Realisation `id`'s input into a fresh r; `thread` in [0, threads) picks the workspace.
  virtual void fill(std::uint64_t id, int thread, beam::Realisation& r) const = 0;
};

// The kind the settings and the resolved contact c call for. `lines` draws the line texture of
// c.line_psd (used by the line kinds only); `threads` workspaces.
std::unique_ptr<BallOnBeamExcitation> make_ball_on_beam_excitation(
    const BallOnBeamSettings& b, const ResolvedContact& c, std::shared_ptr<const texture::LineTextureGenerator> lines,
    int threads);

}  // namespace rollspec::scenes
