#include "src/study/sections/rolling_body_sections.hpp"

#include "src/study/sections/section_keys.hpp"
#include "src/study/sections/vector_keys.hpp"

namespace rollspec::study {

SectionKeys<BodySection> BodySection::declare() {
  using T = BodySection;
  return SectionKeys<T>("body").choice("kind", &T::kind, "what rolls (the seed 000 builders define their own planes)",
                                       BodyKind::beam, kBodyKinds);
}
template struct DeclaredSection<BodySection>;

SectionKeys<PuckSection> PuckSection::declare() {
  using T = PuckSection;
  return SectionKeys<T>("puck")
      .real("half_width", &T::half_width, "m", "walls at x, z = +-half_width (seed 000 example 4.3)", "1", above(0.0))
      .real("force_peak", &T::force_peak, "N", "peak of the triangular force pulse along z", "3e4", any_number())
      .real("moment_peak", &T::moment_peak, "N m", "peak of the triangular moment pulse about y", "1.5e4", any_number())
      .real("pulse", &T::pulse, "s", "duration of the triangular pulse", "0.1", above(0.0));
}
template struct DeclaredSection<PuckSection>;

SectionKeys<FlyingBeamSection> FlyingBeamSection::declare() {
  using T = FlyingBeamSection;
  return SectionKeys<T>("flying_beam")
      .real("force_peak", &T::force_peak, "N", "lateral force at the centre node, ramped up over [0, ramp]", "1e3",
            any_number())
      .real("ramp", &T::ramp, "s", "ramp time of the lateral force", "1", above(0.0))
      .real("wall_distance", &T::wall_distance, "m", "distance of the oblique wall", "1000", above(0.0));
}
template struct DeclaredSection<FlyingBeamSection>;

SectionKeys<StraightBeamSection> StraightBeamSection::declare() {
  using T = StraightBeamSection;
  return SectionKeys<T>("beam")
      .text("start", &T::start, "first end of the straight beam, x,y,z (m)", "0,0,0", vector3)
      .text("end", &T::end, "second end, x,y,z (m)", "10,0,0", vector3)
      .text("up", &T::up, "direction of the section's e2 axis, x,y,z", "0,1,0", vector3)
      .integer("elements", &T::elements, "quadratic 3-node elements", "20", 1, 100000)
      .real("diameter", &T::diameter, "m", "outer diameter (also the contact sphere's diameter)", "0.3", above(0.0))
      .real("inner_diameter", &T::inner_diameter, "m", "inner diameter of a tube (0: solid)", "0", at_least(0.0))
      .real("youngs_modulus", &T::youngs_modulus, "Pa", "Young's modulus", "1e7", above(0.0))
      .real("poisson", &T::poisson, "-", "Poisson's ratio", "0", {-1.0, 0.5, false, true})
      .real("density", &T::density, "kg/m^3", "density", "1e5", above(0.0));
}
template struct DeclaredSection<StraightBeamSection>;

namespace {

// [disc] position: "rest" (on the first plane, placed by the scene) or x,y,z.
Eigen::Vector3d rest_or_vector3(const KeyReader& s, const std::string& key) {
  return s.text(key) == "rest" ? Eigen::Vector3d::Zero() : vector3(s, key);
}

}  // namespace

SectionKeys<DiscSection> DiscSection::declare() {
  using T = DiscSection;
  return SectionKeys<T>("disc")
      .real("radius", &T::radius, "m", "disc radius (contact sphere radius)", "0.2", above(0.0))
      .real("length", &T::length, "m", "disc length along its axis (transverse inertia)", "1", above(0.0))
      .real("mass", &T::mass, "kg", "disc mass", "1000", above(0.0))
      .text("position", &T::position, "centre x,y,z (m); 'rest' puts it on the plane at its static penetration", "rest",
            rest_or_vector3)
      .text("velocity", &T::velocity, "initial velocity x,y,z (m/s)", "0,0,0", vector3)
      .text("angular_velocity", &T::angular_velocity, "initial angular velocity x,y,z (rad/s); the disc's axis is z",
            "0,0,0", vector3);
}
template struct DeclaredSection<DiscSection>;

void StraightBeamSection::finish() {
  if (inner_diameter >= diameter) origin(inner_diameter).refuse("must be smaller than [beam] diameter");
  if ((end - start).norm() == 0.0) origin(end).refuse("coincides with [beam] start");
}

void DiscSection::finish() { at_rest = value_text(position) == "rest"; }

}  // namespace rollspec::study
