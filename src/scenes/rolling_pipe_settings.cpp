#include "src/scenes/rolling_pipe_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "kernels/texture/psd_units.hpp"
#include "src/scenes/study_welch.hpp"
#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {
const double inf = std::numeric_limits<double>::infinity();
const double kPi = 3.141592653589793;
}  // namespace

std::vector<KeySpec> rolling_pipe_keys() {
  std::vector<KeySpec> k = {
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
      real_key("roll", "speed", "m/s", "initial rolling speed v (spin v/r: rolling without slip)", std::string("0.5"),
               0.0, inf, false),
      real_key("roll", "distance", "m", "distance rolled during the record (record length distance/speed)",
               std::string("0.3"), 0.0, inf, false),
      choice_key("roughness", "kind",
                 "line: a line texture along the rolling direction, the same under every node; isotropic: an isotropic "
                 "surface realisation from [surface] (spectral or seed method), different under every node",
                 std::string("line"), {"line", "isotropic"}),
      real_key("roughness", "spacing", "m", "sample spacing of the line texture", std::string("1e-3"), 0.0, inf, false),
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
      real_key("gravity", "acceleration", "m/s^2", "gravity, normal to the mean surface", std::string("9.81"), 0.0, inf,
               false),
      real_key("analysis", "dt", "s", "time step (also the sampling interval of the spectra)", std::string("1e-4"), 0.0,
               inf, false),
      real_key("analysis", "tolerance", "-", "Newton convergence: residual 2-norm relative to the tube's weight",
               std::string("1e-8"), 0.0, 1.0, false),
      text_key("sensors", "positions",
               "sensor positions along the tube as fractions of its length (nearest node), comma-separated",
               std::string("0,0.5,1")),
      bool_key("sensors", "average", "add the mean PSD over sensors", std::string("true")),
      real_key("spectrum", "skip_start", "s", "start of the record left out of the spectra (settling on the surface)",
               std::string("0.02"), 0.0, inf),
  };
  for (auto& key : texture_io::psd_keys()) k.push_back(key);
  for (auto& key : texture_io::surface_keys()) k.push_back(key);
  return k;
}

RollingPipeSettings read_rolling_pipe_settings(const KeyReader& s) {
  using namespace rolling;
  RollingPipeSettings p;
  p.seed = static_cast<std::uint64_t>(s.integer("study.seed"));
  p.psd = texture_io::study_psd(s);
  p.line = s.text("roughness.kind") == "line";
  p.sensor_mean = s.boolean("sensors.average");
  const study::SpectrumSection spectrum = study::SpectrumSection::parse(s);
  p.confidence = spectrum.confidence;
  p.band_min = spectrum.band_min;
  p.band_max = spectrum.band_max;
  const double d = s.real("pipe.diameter"), di = s.real("pipe.inner_diameter");
  if (di >= d) s.refuse("pipe.inner_diameter", "must be smaller than [pipe] diameter");
  p.radius = 0.5 * d;
  p.length = s.real("pipe.length");
  p.section = circular_section(s.real("pipe.youngs_modulus"), s.real("pipe.poisson"), s.real("pipe.density"), d, di);
  p.elements = static_cast<int>(s.integer("pipe.elements"));
  p.speed = s.real("roll.speed");
  p.distance = s.real("roll.distance");
  p.dt = s.real("analysis.dt");
  p.gravity = s.real("gravity.acceleration");
  p.steps = static_cast<std::size_t>(std::llround(p.distance / p.speed / p.dt));
  if (p.steps < 16) s.refuse("roll.distance", "gives fewer than 16 time steps at [analysis] dt");
  if (p.steps > 50'000'000) s.refuse("analysis.dt", "gives more than 5e7 steps per realisation");
  const int nodes = p.nodes();
  // Lumped node mass of the quadratic elements: m_e (1/6, 2/3, 1/6), so an interior end node
  // carries m_e/3 and a mid node 2 m_e/3; the stiffest contact oscillation is at the lightest.
  const double m_e = p.section.rhoA * p.length / p.elements;
  const double m_light = m_e / 6.0, m_mid = 2.0 * m_e / 3.0;
  p.law.radius = p.radius;
  p.law.eps_n = s.real("contact.penalty_normal");
  p.law.eps_t = s.real("contact.penalty_tangential");
  p.law.mu = s.real("contact.friction");
  p.law.rolling = s.boolean("contact.rolling");
  p.damping_ratio = s.real("contact.damping_ratio");
  // The damper of each node follows its lumped mass: c = 2 zeta sqrt(eps_n m_node).
  for (int i = 0; i < nodes; ++i) {
    const double mn = i % 2 == 1 ? m_mid : (i == 0 || i == nodes - 1 ? m_light : 2.0 * m_light);
    p.node_damping.push_back(2.0 * p.damping_ratio * std::sqrt(p.law.eps_n * mn));
  }
  // The step must resolve the contact oscillation of the lightest node: dt <= T_c / 20 (kernels/README.md D-23).
  const double tc = 2.0 * kPi * std::sqrt(m_light / p.law.eps_n);
  if (p.dt > tc / 20.0) {
    std::ostringstream m;
    m << "= " << p.dt
      << " s does not resolve the contact oscillation of the lightest node (T_c = 2 pi sqrt(m/eps_n) = " << tc
      << " s); allowed: dt <= T_c/20 = " << tc / 20.0 << " s";
    s.refuse("analysis.dt", m.str());
  }
  // Sensors: nearest nodes.
  for (double f : s.numbers("sensors.positions")) {
    if (!(f >= 0.0 && f <= 1.0))
      s.refuse("sensors.positions", "fraction " + std::to_string(f) + " lies outside [0, 1]");
    p.sensor_nodes.push_back(static_cast<int>(std::lround(f * (nodes - 1))));
    p.sensor_fractions.push_back(f);
  }
  if (p.sensor_nodes.empty()) s.refuse("sensors.positions", "lists no sensor; allowed: fractions in [0, 1]");
  // The rolled strip: x from -margin to distance + margin (the spheres' footprint and a cell).
  p.x_lo = -(p.radius + 0.02 * p.distance + 0.01);
  p.x_hi = p.distance + p.radius + 0.02 * p.distance + 0.01;
  if (p.line) {
    p.spacing = s.real("roughness.spacing");
    p.line_samples = static_cast<std::size_t>(std::ceil((p.x_hi - p.x_lo) / p.spacing)) + 1;
    if (p.line_samples > (1u << 24))
      s.refuse("roughness.spacing", "gives more than 2^24 samples over the rolled strip");
  } else {
    p.spacing = s.real("surface.spacing");
    const double nx = static_cast<double>(s.integer("surface.nx")), ny = static_cast<double>(s.integer("surface.ny"));
    const double need_x = p.x_hi - p.x_lo, need_y = p.length + 2.0 * p.radius + 2.0 * p.spacing;
    if ((nx - 1.0) * p.spacing < need_x || (ny - 1.0) * p.spacing < need_y) {
      std::ostringstream m;
      m << "the surface grid covers " << (nx - 1.0) * p.spacing << " m x " << (ny - 1.0) * p.spacing
        << " m; allowed: at least " << need_x << " m along the rolling direction (nx) and " << need_y
        << " m along the tube (ny)";
      s.refuse("surface.nx", m.str());
    }
  }
  // A priori single-point check with the PSD's rms curvature sqrt(m4) over the sampled
  // band: a sphere sharper than the typical valley would touch at two points almost everywhere.
  const double k_hi = std::min(p.psd.support_max, kPi / p.spacing);
  const double k_lo = std::max(p.psd.support_min, 1e-6 * k_hi);  // k^4 G: nothing lost below
  const double m4 = k_hi > k_lo ? texture::integrate_psd(p.psd, k_lo, k_hi, 4.0) : 0.0;
  p.rms_curvature = std::sqrt(m4);
  if (p.radius * p.rms_curvature > 0.5) {
    std::ostringstream m;
    m << "rms curvature of the roughness sqrt(m4) = " << p.rms_curvature << " 1/m times the contact radius " << p.radius
      << " m is " << p.radius * p.rms_curvature
      << ": the node spheres would touch at two points in most valleys; allowed: r sqrt(m4) <= 0.5 (raise the "
         "short wavelength cut-off or the roughness spacing)";
    s.refuse(p.line ? "roughness.spacing" : "surface.spacing", m.str());
  }
  p.samples = p.steps + 1;
  p.skip = static_cast<std::size_t>(std::ceil(spectrum.skip_start / p.dt));
  if (p.skip >= p.samples)
    spectrum.skip_start_origin.refuse("leaves nothing of the record (" + std::to_string(p.samples) + " samples)");
  const auto segment = static_cast<std::size_t>(spectrum.segment);
  if (segment > p.samples - p.skip)
    spectrum.segment_origin.refuse("is longer than the analysed record (" + std::to_string(p.samples - p.skip) +
                                   " samples = (distance / speed - skip_start) / dt)");
  p.welch = study_welch_config(spectrum, 1.0 / p.dt);
  p.solver.analysis = Analysis::Dynamic;
  p.solver.max_iterations = 30;
  p.solver.max_cuts = 12;
  p.solver.max_line_search = 8;
  p.solver.disp_tol = 1e-14;
  p.solver.force_tol = s.real("analysis.tolerance") * p.section.rhoA * p.length * p.gravity;
  return p;
}

}  // namespace rollspec::scenes
