#include "src/study/sections/rolling_pipe_sections.hpp"

#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<KeySpec> PipeSection::keys() {
  return {
      real_key("pipe", "length", "m", "tube length (its axis lies across the rolling direction)", std::string("1"), 0.0,
               inf, false),
      real_key("pipe", "diameter", "m", "outer diameter (the contact spheres' diameter)", std::string("0.06"), 0.0, inf,
               false),
      real_key("pipe", "inner_diameter", "m", "inner diameter (0: solid bar)", std::string("0.052"), 0.0, inf),
      real_key("pipe", "youngs_modulus", "Pa", "Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("pipe", "poisson", "-", "Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("pipe", "density", "kg/m^3", "density", std::string("7850"), 0.0, inf, false),
      integer_key("pipe", "elements", "quadratic 3-node beam elements along the tube (2n + 1 contact nodes)",
                  std::string("4"), 1, 1000),
  };
}

PipeSection PipeSection::parse(const KeyReader& s) {
  PipeSection p;
  p.diameter = s.real("pipe.diameter");
  p.inner_diameter = s.real("pipe.inner_diameter");
  if (p.inner_diameter >= p.diameter) s.refuse("pipe.inner_diameter", "must be smaller than [pipe] diameter");
  p.length = s.real("pipe.length");
  p.youngs_modulus = s.real("pipe.youngs_modulus");
  p.poisson = s.real("pipe.poisson");
  p.density = s.real("pipe.density");
  p.elements = s.integer("pipe.elements");
  return p;
}

std::vector<KeySpec> RollSection::keys() {
  return {
      real_key("roll", "speed", "m/s", "initial rolling speed v (spin v/r: rolling without slip)", std::string("0.5"),
               0.0, inf, false),
      real_key("roll", "distance", "m", "distance rolled during the record (record length distance/speed)",
               std::string("0.3"), 0.0, inf, false),
  };
}

RollSection RollSection::parse(const KeyReader& s) {
  return {s.real("roll.speed"), s.real("roll.distance"), {s.where("roll.distance")}};
}

std::vector<KeySpec> PipeRoughnessSection::keys() {
  return {
      choice_key("roughness", "kind", "the roughness under the contact nodes", PipeRoughnessKind::line,
                 kPipeRoughnessKinds),
      real_key("roughness", "spacing", "m", "sample spacing of the line texture", std::string("1e-3"), 0.0, inf, false),
  };
}

PipeRoughnessSection PipeRoughnessSection::parse(const KeyReader& s) {
  return {read_choice(s, "roughness.kind", kPipeRoughnessKinds) == PipeRoughnessKind::line,
          s.real("roughness.spacing"),
          {s.where("roughness.spacing")}};
}

std::vector<KeySpec> PipeContactSection::keys() {
  return {
      real_key("contact", "friction", "-", "Coulomb coefficient mu (0: frictionless, the tube slides)",
               std::string("0.3"), 0.0, inf),
      real_key("contact", "penalty_normal", "N/m", "normal penalty eps_n per contact node", std::string("2e7"), 0.0,
               inf, false),
      real_key("contact", "penalty_tangential", "N/m", "tangential penalty eps_t per contact node", std::string("2e6"),
               0.0, inf, false),
      real_key("contact", "damping_ratio", "-",
               "normal contact damper per node as a ratio of critical on the node's lumped mass: c = 2 zeta sqrt(eps_n "
               "m_node)",
               std::string("0.1"), 0.0, 10.0),
      bool_key("contact", "rolling", "rolling correction of the tangential gap (false: seed 000's 'no rolling')",
               std::string("true")),
  };
}

PipeContactSection PipeContactSection::parse(const KeyReader& s) {
  PipeContactSection c;
  c.friction = s.real("contact.friction");
  c.penalty_normal = s.real("contact.penalty_normal");
  c.penalty_tangential = s.real("contact.penalty_tangential");
  c.damping_ratio = s.real("contact.damping_ratio");
  c.rolling = s.boolean("contact.rolling");
  return c;
}

std::vector<KeySpec> PipeGravitySection::keys() {
  return {
      real_key("gravity", "acceleration", "m/s^2", "gravity, normal to the mean surface", std::string("9.81"), 0.0, inf,
               false),
  };
}

PipeGravitySection PipeGravitySection::parse(const KeyReader& s) { return {s.real("gravity.acceleration")}; }

std::vector<KeySpec> PipeAnalysisSection::keys() {
  return {
      real_key("analysis", "dt", "s", "time step (also the sampling interval of the spectra)", std::string("1e-4"), 0.0,
               inf, false),
      real_key("analysis", "tolerance", "-", "Newton convergence: residual 2-norm relative to the tube's weight",
               std::string("1e-8"), 0.0, 1.0, false),
  };
}

PipeAnalysisSection PipeAnalysisSection::parse(const KeyReader& s) {
  return {s.real("analysis.dt"), s.real("analysis.tolerance"), {s.where("analysis.dt")}};
}

std::vector<KeySpec> PipeSensorsSection::keys() {
  return {
      text_key("sensors", "positions",
               "sensor positions along the tube as fractions of its length (nearest node), comma-separated",
               std::string("0,0.5,1")),
      bool_key("sensors", "average", "add the mean PSD over sensors", std::string("true")),
  };
}

PipeSensorsSection PipeSensorsSection::parse(const KeyReader& s) {
  return {s.numbers("sensors.positions"), s.boolean("sensors.average"), {s.where("sensors.positions")}};
}

}  // namespace rollspec::study
