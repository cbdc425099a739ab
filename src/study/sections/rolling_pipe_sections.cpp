#include "src/study/sections/rolling_pipe_sections.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<PipeSection> PipeSection::declare() {
  using T = PipeSection;
  return SectionKeys<T>("pipe")
      .real("length", &T::length, "m", "tube length (its axis lies across the rolling direction)", "1", above(0.0))
      .real("diameter", &T::diameter, "m", "outer diameter (the contact spheres' diameter)", "0.06", above(0.0))
      .real("inner_diameter", &T::inner_diameter, "m", "inner diameter (0: solid bar)", "0.052", at_least(0.0))
      .real("youngs_modulus", &T::youngs_modulus, "Pa", "Young's modulus", "210e9", above(0.0))
      .real("poisson", &T::poisson, "-", "Poisson's ratio", "0.3", {-1.0, 0.5, false, false})
      .real("density", &T::density, "kg/m^3", "density", "7850", above(0.0))
      .integer("elements", &T::elements, "quadratic 3-node beam elements along the tube (2n + 1 contact nodes)", "4", 1,
               1000);
}
template struct DeclaredSection<PipeSection>;

SectionKeys<RollSection> RollSection::declare() {
  using T = RollSection;
  return SectionKeys<T>("roll")
      .real("speed", &T::speed, "m/s", "initial rolling speed v (spin v/r: rolling without slip)", "0.5", above(0.0))
      .real("distance", &T::distance, "m", "distance rolled during the record (record length distance/speed)", "0.3",
            above(0.0));
}
template struct DeclaredSection<RollSection>;

SectionKeys<PipeRoughnessSection> PipeRoughnessSection::declare() {
  using T = PipeRoughnessSection;
  return SectionKeys<T>("roughness")
      .choice("kind", &T::kind, "the roughness under the contact nodes", PipeRoughnessKind::line, kPipeRoughnessKinds)
      .real("spacing", &T::spacing, "m", "sample spacing of the line texture", "1e-3", above(0.0));
}
template struct DeclaredSection<PipeRoughnessSection>;

SectionKeys<PipeContactSection> PipeContactSection::declare() {
  using T = PipeContactSection;
  return SectionKeys<T>("contact")
      .real("friction", &T::friction, "-", "Coulomb coefficient mu (0: frictionless, the tube slides)", "0.3",
            at_least(0.0))
      .real("penalty_normal", &T::penalty_normal, "N/m", "normal penalty eps_n per contact node", "2e7", above(0.0))
      .real("penalty_tangential", &T::penalty_tangential, "N/m", "tangential penalty eps_t per contact node", "2e6",
            above(0.0))
      .real("damping_ratio", &T::damping_ratio, "-",
            "normal contact damper per node as a ratio of critical on the node's lumped mass: c = 2 zeta "
            "sqrt(eps_n m_node)",
            "0.1", within(0.0, 10.0))
      .boolean("rolling", &T::rolling, "rolling correction of the tangential gap (false: seed 000's 'no rolling')",
               "true");
}
template struct DeclaredSection<PipeContactSection>;

SectionKeys<PipeGravitySection> PipeGravitySection::declare() {
  using T = PipeGravitySection;
  return SectionKeys<T>("gravity").real("acceleration", &T::acceleration, "m/s^2",
                                        "gravity, normal to the mean surface", "9.81", above(0.0));
}
template struct DeclaredSection<PipeGravitySection>;

SectionKeys<PipeAnalysisSection> PipeAnalysisSection::declare() {
  using T = PipeAnalysisSection;
  return SectionKeys<T>("analysis")
      .real("dt", &T::dt, "s", "time step (also the sampling interval of the spectra)", "1e-4", above(0.0))
      .real("tolerance", &T::tolerance, "-", "Newton convergence: residual 2-norm relative to the tube's weight",
            "1e-8", {0.0, 1.0, false});
}
template struct DeclaredSection<PipeAnalysisSection>;

SectionKeys<PipeSensorsSection> PipeSensorsSection::declare() {
  using T = PipeSensorsSection;
  return SectionKeys<T>("sensors")
      .text("positions", &T::positions,
            "sensor positions along the tube as fractions of its length (nearest node), comma-separated", "0,0.5,1",
            number_list)
      .boolean("average", &T::average, "add the mean PSD over sensors", "true");
}
template struct DeclaredSection<PipeSensorsSection>;

void PipeSection::finish() {
  if (inner_diameter >= diameter) origin(inner_diameter).refuse("must be smaller than [pipe] diameter");
}

void PipeRoughnessSection::finish() { line = kind == PipeRoughnessKind::line; }

}  // namespace rollspec::study
