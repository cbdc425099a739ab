#include "src/study/sections/rolling_body_sections.hpp"

#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/vector_keys.hpp"

namespace rollspec::study {

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<KeySpec> BodySection::keys() {
  return {
      choice_key("body", "kind", "what rolls (the seed 000 builders define their own planes)", BodyKind::beam,
                 kBodyKinds),
  };
}

BodySection BodySection::parse(const KeyReader& s) { return {read_choice(s, "body.kind", kBodyKinds)}; }

std::vector<KeySpec> PuckSection::keys() {
  return {
      real_key("puck", "half_width", "m", "walls at x, z = +-half_width (seed 000 example 4.3)", std::string("1"), 0.0,
               inf, false),
      real_key("puck", "force_peak", "N", "peak of the triangular force pulse along z", std::string("3e4"), -inf, inf),
      real_key("puck", "moment_peak", "N m", "peak of the triangular moment pulse about y", std::string("1.5e4"), -inf,
               inf),
      real_key("puck", "pulse", "s", "duration of the triangular pulse", std::string("0.1"), 0.0, inf, false),
  };
}

PuckSection PuckSection::parse(const KeyReader& s) {
  PuckSection p;
  p.half_width = s.real("puck.half_width");
  p.force_peak = s.real("puck.force_peak");
  p.moment_peak = s.real("puck.moment_peak");
  p.pulse = s.real("puck.pulse");
  return p;
}

std::vector<KeySpec> FlyingBeamSection::keys() {
  return {
      real_key("flying_beam", "force_peak", "N", "lateral force at the centre node, ramped up over [0, ramp]",
               std::string("1e3"), -inf, inf),
      real_key("flying_beam", "ramp", "s", "ramp time of the lateral force", std::string("1"), 0.0, inf, false),
      real_key("flying_beam", "wall_distance", "m", "distance of the oblique wall", std::string("1000"), 0.0, inf,
               false),
  };
}

FlyingBeamSection FlyingBeamSection::parse(const KeyReader& s) {
  FlyingBeamSection f;
  f.force_peak = s.real("flying_beam.force_peak");
  f.ramp = s.real("flying_beam.ramp");
  f.wall_distance = s.real("flying_beam.wall_distance");
  return f;
}

std::vector<KeySpec> StraightBeamSection::keys() {
  return {
      text_key("beam", "start", "first end of the straight beam, x,y,z (m)", std::string("0,0,0")),
      text_key("beam", "end", "second end, x,y,z (m)", std::string("10,0,0")),
      text_key("beam", "up", "direction of the section's e2 axis, x,y,z", std::string("0,1,0")),
      integer_key("beam", "elements", "quadratic 3-node elements", std::string("20"), 1, 100000),
      real_key("beam", "diameter", "m", "outer diameter (also the contact sphere's diameter)", std::string("0.3"), 0.0,
               inf, false),
      real_key("beam", "inner_diameter", "m", "inner diameter of a tube (0: solid)", std::string("0"), 0.0, inf),
      real_key("beam", "youngs_modulus", "Pa", "Young's modulus", std::string("1e7"), 0.0, inf, false),
      real_key("beam", "poisson", "-", "Poisson's ratio", std::string("0"), -1.0, 0.5, false, true),
      real_key("beam", "density", "kg/m^3", "density", std::string("1e5"), 0.0, inf, false),
  };
}

StraightBeamSection StraightBeamSection::parse(const KeyReader& s) {
  StraightBeamSection b;
  b.diameter = s.real("beam.diameter");
  b.inner_diameter = s.real("beam.inner_diameter");
  if (b.inner_diameter >= b.diameter) s.refuse("beam.inner_diameter", "must be smaller than [beam] diameter");
  b.youngs_modulus = s.real("beam.youngs_modulus");
  b.poisson = s.real("beam.poisson");
  b.density = s.real("beam.density");
  b.start = vector3(s, "beam.start");
  b.end = vector3(s, "beam.end");
  if ((b.end - b.start).norm() == 0.0) s.refuse("beam.end", "coincides with [beam] start");
  b.elements = s.integer("beam.elements");
  b.up = vector3(s, "beam.up");
  return b;
}

std::vector<KeySpec> DiscSection::keys() {
  return {
      real_key("disc", "radius", "m", "disc radius (contact sphere radius)", std::string("0.2"), 0.0, inf, false),
      real_key("disc", "length", "m", "disc length along its axis (transverse inertia)", std::string("1"), 0.0, inf,
               false),
      real_key("disc", "mass", "kg", "disc mass", std::string("1000"), 0.0, inf, false),
      text_key("disc", "position", "centre x,y,z (m); 'rest' puts it on the plane at its static penetration",
               std::string("rest")),
      text_key("disc", "velocity", "initial velocity x,y,z (m/s)", std::string("0,0,0")),
      text_key("disc", "angular_velocity", "initial angular velocity x,y,z (rad/s); the disc's axis is z",
               std::string("0,0,0")),
  };
}

DiscSection DiscSection::parse(const KeyReader& s) {
  DiscSection d;
  d.radius = s.real("disc.radius");
  d.mass = s.real("disc.mass");
  d.length = s.real("disc.length");
  d.at_rest = s.text("disc.position") == "rest";
  d.position = d.at_rest ? Eigen::Vector3d::Zero() : vector3(s, "disc.position");
  d.velocity = vector3(s, "disc.velocity");
  d.angular_velocity = vector3(s, "disc.angular_velocity");
  return d;
}

}  // namespace rollspec::study
