#include "src/study/sections/rolling_body_sections.hpp"

#include "src/study/sections/section_keys.hpp"
#include "src/study/sections/vector_keys.hpp"

namespace rollspec::study {

namespace {

const SectionKeys<BodySection>& body_keys() {
  using T = BodySection;
  static const auto k = SectionKeys<T>("body").choice(
      "kind", &T::kind, "what rolls (the seed 000 builders define their own planes)", BodyKind::beam, kBodyKinds);
  return k;
}

const SectionKeys<PuckSection>& puck_keys() {
  using T = PuckSection;
  static const auto k =
      SectionKeys<T>("puck")
          .real("half_width", &T::half_width, "m", "walls at x, z = +-half_width (seed 000 example 4.3)", "1",
                above(0.0))
          .real("force_peak", &T::force_peak, "N", "peak of the triangular force pulse along z", "3e4", any_number())
          .real("moment_peak", &T::moment_peak, "N m", "peak of the triangular moment pulse about y", "1.5e4",
                any_number())
          .real("pulse", &T::pulse, "s", "duration of the triangular pulse", "0.1", above(0.0));
  return k;
}

const SectionKeys<FlyingBeamSection>& flying_beam_keys() {
  using T = FlyingBeamSection;
  static const auto k =
      SectionKeys<T>("flying_beam")
          .real("force_peak", &T::force_peak, "N", "lateral force at the centre node, ramped up over [0, ramp]", "1e3",
                any_number())
          .real("ramp", &T::ramp, "s", "ramp time of the lateral force", "1", above(0.0))
          .real("wall_distance", &T::wall_distance, "m", "distance of the oblique wall", "1000", above(0.0));
  return k;
}

const SectionKeys<StraightBeamSection>& straight_beam_keys() {
  using T = StraightBeamSection;
  static const auto k =
      SectionKeys<T>("beam")
          .text("start", &T::start, "first end of the straight beam, x,y,z (m)", "0,0,0", vector3)
          .text("end", &T::end, "second end, x,y,z (m)", "10,0,0", vector3)
          .text("up", &T::up, "direction of the section's e2 axis, x,y,z", "0,1,0", vector3)
          .integer("elements", &T::elements, "quadratic 3-node elements", "20", 1, 100000)
          .real("diameter", &T::diameter, "m", "outer diameter (also the contact sphere's diameter)", "0.3", above(0.0))
          .real("inner_diameter", &T::inner_diameter, "m", "inner diameter of a tube (0: solid)", "0", at_least(0.0))
          .real("youngs_modulus", &T::youngs_modulus, "Pa", "Young's modulus", "1e7", above(0.0))
          .real("poisson", &T::poisson, "-", "Poisson's ratio", "0", {-1.0, 0.5, false, true})
          .real("density", &T::density, "kg/m^3", "density", "1e5", above(0.0));
  return k;
}

// [disc] position: "rest" (on the first plane, placed by the scene) or x,y,z.
Eigen::Vector3d rest_or_vector3(const KeyReader& s, const std::string& key) {
  return s.text(key) == "rest" ? Eigen::Vector3d::Zero() : vector3(s, key);
}

const SectionKeys<DiscSection>& disc_keys() {
  using T = DiscSection;
  static const auto k =
      SectionKeys<T>("disc")
          .real("radius", &T::radius, "m", "disc radius (contact sphere radius)", "0.2", above(0.0))
          .real("length", &T::length, "m", "disc length along its axis (transverse inertia)", "1", above(0.0))
          .real("mass", &T::mass, "kg", "disc mass", "1000", above(0.0))
          .text("position", &T::position, "centre x,y,z (m); 'rest' puts it on the plane at its static penetration",
                "rest", rest_or_vector3)
          .text("velocity", &T::velocity, "initial velocity x,y,z (m/s)", "0,0,0", vector3)
          .text("angular_velocity", &T::angular_velocity,
                "initial angular velocity x,y,z (rad/s); the disc's axis is z", "0,0,0", vector3);
  return k;
}

}  // namespace

std::vector<KeySpec> BodySection::keys() { return body_keys().keys(); }
BodySection BodySection::parse(const KeyReader& s) { return body_keys().read(s); }

std::vector<KeySpec> PuckSection::keys() { return puck_keys().keys(); }
PuckSection PuckSection::parse(const KeyReader& s) { return puck_keys().read(s); }

std::vector<KeySpec> FlyingBeamSection::keys() { return flying_beam_keys().keys(); }
FlyingBeamSection FlyingBeamSection::parse(const KeyReader& s) { return flying_beam_keys().read(s); }

std::vector<KeySpec> StraightBeamSection::keys() { return straight_beam_keys().keys(); }

StraightBeamSection StraightBeamSection::parse(const KeyReader& s) {
  const StraightBeamSection b = straight_beam_keys().read(s);
  if (b.inner_diameter >= b.diameter) b.origin(b.inner_diameter).refuse("must be smaller than [beam] diameter");
  if ((b.end - b.start).norm() == 0.0) b.origin(b.end).refuse("coincides with [beam] start");
  return b;
}

std::vector<KeySpec> DiscSection::keys() { return disc_keys().keys(); }

DiscSection DiscSection::parse(const KeyReader& s) {
  DiscSection d = disc_keys().read(s);
  d.at_rest = d.value_text(d.position) == "rest";
  return d;
}

}  // namespace rollspec::study
