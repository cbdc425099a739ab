#include "src/scenes/rolling_pipe/rolling_pipe_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "kernels/texture/psd_units.hpp"
#include "src/scenes/study_welch.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_grid_section.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::scenes {

using study::PipeAnalysisSection;
using study::PipeContactSection;
using study::PipeSection;
using study::PipeSensorsSection;
using study::RollSection;
using study::TextureSection;

using namespace study;

namespace {
const double kPi = 3.141592653589793;
}  // namespace

std::vector<KeySpec> rolling_pipe_keys() {
  std::vector<KeySpec> k = PipeSection::keys();
  for (auto& key : RollSection::keys()) k.push_back(key);
  for (auto& key : PipeRoughnessSection::keys()) k.push_back(key);
  for (auto& key : PipeContactSection::keys()) k.push_back(key);
  for (auto& key : PipeGravitySection::keys()) k.push_back(key);
  for (auto& key : PipeAnalysisSection::keys()) k.push_back(key);
  for (auto& key : PipeSensorsSection::keys()) k.push_back(key);
  // skip_start is read by SpectrumSection; its doc is this scene's.
  k.push_back(
      SpectrumSection::skip_start_key("start of the record left out of the spectra (settling on the surface)", "0.02"));
  for (auto& key : texture_io::psd_keys()) k.push_back(key);
  for (auto& key : texture_io::surface_keys()) k.push_back(key);
  return k;
}

RollingPipeSettings read_rolling_pipe_settings(const KeyReader& s) {
  using namespace rolling;
  RollingPipeSettings p;
  p.seed = StudySection::parse(s).seed;
  p.texture = study::TextureSection::parse(s);
  p.psd = texture_io::study_psd(p.texture);
  const auto roughness = PipeRoughnessSection::parse(s);
  p.line_keys =
      texture_io::LineGeneratorKeys::of(p.texture, roughness.origin(roughness.spacing), "[roughness] spacing");
  if (!roughness.line) p.surface = texture_io::with_profile_values(p.texture, study::SurfaceSection::parse(s));
  p.line = roughness.line;
  const auto sensors = PipeSensorsSection::parse(s);
  p.sensor_mean = sensors.average;
  const study::SpectrumSection spectrum = study::SpectrumSection::parse(s);
  p.confidence = spectrum.confidence;
  p.band_min = spectrum.band_min;
  p.band_max = spectrum.band_max;
  const auto pipe = PipeSection::parse(s);
  p.radius = 0.5 * pipe.diameter;
  p.length = pipe.length;
  p.section = circular_section(pipe.youngs_modulus, pipe.poisson, pipe.density, pipe.diameter, pipe.inner_diameter);
  p.elements = static_cast<int>(pipe.elements);
  const auto roll = RollSection::parse(s);
  p.speed = roll.speed;
  p.distance = roll.distance;
  const auto analysis = PipeAnalysisSection::parse(s);
  p.dt = analysis.dt;
  p.gravity = PipeGravitySection::parse(s).acceleration;
  p.steps = static_cast<std::size_t>(std::llround(p.distance / p.speed / p.dt));
  if (p.steps < 16) roll.origin(roll.distance).refuse("gives fewer than 16 time steps at [analysis] dt");
  if (p.steps > 50'000'000) analysis.origin(analysis.dt).refuse("gives more than 5e7 steps per realisation");
  const int nodes = p.nodes();
  // Lumped node mass of the quadratic elements: m_e (1/6, 2/3, 1/6), so an interior end node
  // carries m_e/3 and a mid node 2 m_e/3; the stiffest contact oscillation is at the lightest.
  const double m_e = p.section.rhoA * p.length / p.elements;
  const double m_light = m_e / 6.0, m_mid = 2.0 * m_e / 3.0;
  p.law.radius = p.radius;
  const auto contact = PipeContactSection::parse(s);
  p.law.eps_n = contact.penalty_normal;
  p.law.eps_t = contact.penalty_tangential;
  p.law.mu = contact.friction;
  p.law.rolling = contact.rolling;
  p.damping_ratio = contact.damping_ratio;
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
    analysis.origin(analysis.dt).refuse(m.str());
  }
  // Sensors: nearest nodes.
  for (double f : sensors.positions) {
    if (!(f >= 0.0 && f <= 1.0))
      sensors.origin(sensors.positions).refuse("fraction " + std::to_string(f) + " lies outside [0, 1]");
    p.sensor_nodes.push_back(static_cast<int>(std::lround(f * (nodes - 1))));
    p.sensor_fractions.push_back(f);
  }
  if (p.sensor_nodes.empty()) sensors.origin(sensors.positions).refuse("lists no sensor; allowed: fractions in [0, 1]");
  // The rolled strip: x from -margin to distance + margin (the spheres' footprint and a cell).
  p.x_lo = -(p.radius + 0.02 * p.distance + 0.01);
  p.x_hi = p.distance + p.radius + 0.02 * p.distance + 0.01;
  KeyOrigin spacing_origin = roughness.origin(roughness.spacing);  // the key that set the spacing
  if (p.line) {
    p.spacing = roughness.spacing;
    p.line_samples = static_cast<std::size_t>(std::ceil((p.x_hi - p.x_lo) / p.spacing)) + 1;
    if (p.line_samples > (1u << 24))
      roughness.origin(roughness.spacing).refuse("gives more than 2^24 samples over the rolled strip");
  } else {
    const auto grid = SurfaceGridSection::parse(s);
    spacing_origin = grid.spacing_origin;
    p.spacing = grid.spacing;
    const double nx = static_cast<double>(grid.nx), ny = static_cast<double>(grid.ny);
    const double need_x = p.x_hi - p.x_lo, need_y = p.length + 2.0 * p.radius + 2.0 * p.spacing;
    if ((nx - 1.0) * p.spacing < need_x || (ny - 1.0) * p.spacing < need_y) {
      std::ostringstream m;
      m << "the surface grid covers " << (nx - 1.0) * p.spacing << " m x " << (ny - 1.0) * p.spacing
        << " m; allowed: at least " << need_x << " m along the rolling direction (nx) and " << need_y
        << " m along the tube (ny)";
      grid.nx_origin.refuse(m.str());
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
    spacing_origin.refuse(m.str());
  }
  p.samples = p.steps + 1;
  p.skip = static_cast<std::size_t>(std::ceil(spectrum.skip_start / p.dt));
  check_analysed_record(spectrum, p.samples, p.skip, "(distance / speed - skip_start) / dt");
  p.welch = study_welch_config(spectrum, 1.0 / p.dt);
  p.solver.analysis = Analysis::Dynamic;
  p.solver.max_iterations = 30;
  p.solver.max_cuts = 12;
  p.solver.max_line_search = 8;
  p.solver.disp_tol = 1e-14;
  p.solver.force_tol = analysis.tolerance * p.section.rhoA * p.length * p.gravity;
  return p;
}

// The step is set against the default contact penalty (the key's default is too coarse for it).
std::vector<FirstKey> rolling_pipe_first_keys() {
  return {first_key(&PipeSection::length),
          first_key(&PipeSection::diameter),
          first_key(&PipeSection::inner_diameter),
          first_key(&RollSection::speed),
          first_key(&RollSection::distance),
          first_key(&TextureSection::rms),
          first_key(&PipeContactSection::friction),
          first_key(&PipeContactSection::penalty_normal),
          first_key(&PipeAnalysisSection::dt, "2.5e-5"),
          first_key(&PipeSensorsSection::positions)};
}

}  // namespace rollspec::scenes
