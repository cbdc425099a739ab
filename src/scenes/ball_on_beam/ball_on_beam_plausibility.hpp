#pragma once
// The physics of a ball-on-beam study checked before any work: the Hertz contact against the ball
// and the beam, the beam's static deflection under the ball, the modes against the output's band,
// the roughness's wavelengths against the speed and the band. A clearly impossible study is refused
// (config_error naming the key, its value and the derived quantity); a legal but suspect one gets a
// warning line each, which `plan` lists and `run` prints on stderr.
#include <string>
#include <vector>

namespace rollspec::scenes {

struct BallOnBeamSettings;

// Refuses an impossible study; returns the warnings ("file:line: [section] key = value: why").
std::vector<std::string> check_ball_on_beam_plausibility(const BallOnBeamSettings& b);

// The loss-of-contact share at which a nonlinear law's result is flagged (the linearised law is
// flagged at any loss of contact: its linearisation assumes the contact never opens).
constexpr double loss_of_contact_warning_share = 0.05;

// The warning line for a result's loss-of-contact share, or "" when there is nothing to say.
std::string loss_of_contact_warning(double share, bool linearised);

}  // namespace rollspec::scenes
