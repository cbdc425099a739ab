#pragma once
// The body sections of scene rolling-beam, read once: [body] kind, the seed 000 builders' [puck]
// and [flying_beam], the straight [beam] and the rigid [disc]. The scene parses only the sections
// its kind uses, so keys of another kind are never read.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class BodyKind { beam, disc, puck, flying_beam };

inline constexpr ChoiceTable<BodyKind, 4> kBodyKinds{{
    {BodyKind::beam, "beam", "a geometrically exact beam"},
    {BodyKind::disc, "disc", "a rigid disc, one node"},
    {BodyKind::puck, "puck", "seed 000 builder 4.3: four walls, [puck] keys"},
    {BodyKind::flying_beam, "flying-beam", "seed 000 builder 4.4: floor and an oblique wall"},
}};

struct BodySection : DeclaredSection<BodySection> {
  BodyKind kind = BodyKind::beam;

  static SectionKeys<BodySection> declare();
};

struct PuckSection : DeclaredSection<PuckSection> {
  double half_width = 0.0, force_peak = 0.0, moment_peak = 0.0, pulse = 0.0;

  static SectionKeys<PuckSection> declare();
};

struct FlyingBeamSection : DeclaredSection<FlyingBeamSection> {
  double force_peak = 0.0, ramp = 0.0, wall_distance = 0.0;

  static SectionKeys<FlyingBeamSection> declare();
};

// [beam] of rolling-beam (not ball-on-beam's modal beam); inner_diameter < diameter and distinct
// ends are checked here.
struct StraightBeamSection : DeclaredSection<StraightBeamSection> {
  Eigen::Vector3d start, end, up;
  long long elements = 0;
  double diameter = 0.0, inner_diameter = 0.0, youngs_modulus = 0.0, poisson = 0.0, density = 0.0;

  static SectionKeys<StraightBeamSection> declare();
  void finish();  // checks across its keys, once they are read
};

struct DiscSection : DeclaredSection<DiscSection> {
  double radius = 0.0, length = 0.0, mass = 0.0;
  bool at_rest = true;       // position = rest: on the first plane at its static penetration
  Eigen::Vector3d position;  // when not at rest
  Eigen::Vector3d velocity, angular_velocity;

  static SectionKeys<DiscSection> declare();
  void finish();  // at_rest from position
};

}  // namespace rollspec::study
