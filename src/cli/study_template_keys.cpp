#include "src/cli/study_template_keys.hpp"

#include <map>

namespace rollspec::cli {

namespace {
// Keys a rig is described by first. Starting values only where the default cannot run as it
// stands (a required key, rolling-pipe's time step against its default contact penalty, texture's line
// spacing against its default short cut-off, ball-on-beam's roughness: the key's 1 um rms makes the template's
// 20 mm ball lose contact 81 % of the time, 30 nm (a fine ground track) keeps it in contact).
const std::map<std::string, std::vector<FirstKey>>& scene_first_keys() {
  static const std::map<std::string, std::vector<FirstKey>> table = {
      {"random-oscillator",
       {{"oscillator.mass", {}},
        {"oscillator.natural_frequency", "50"},
        {"oscillator.damping_ratio", {}},
        {"force.spectrum", {}},
        {"force.level", {}},
        {"signal.sample_rate", {}},
        {"signal.duration", {}},
        {"spectrum.segment", {}},
        {"spectrum.band_min", {}},
        {"spectrum.band_max", "800"}}},
      {"ball-on-beam",
       {{"beam.length", {}},
        {"beam.width", {}},
        {"beam.thickness", {}},
        {"beam.youngs_modulus", {}},
        {"beam.density", {}},
        {"ball.radius", {}},
        {"ball.density", {}},
        {"ball.speed", {}},
        {"ball.start", {}},
        {"ball.end", {}},
        {"texture.source", {}},
        {"texture.rms", "3e-8"},
        {"sensors.positions", {}}}},
      {"rolling-beam",
       {{"body.kind", {}},
        {"beam.start", {}},
        {"beam.end", {}},
        {"beam.diameter", {}},
        {"beam.youngs_modulus", {}},
        {"beam.density", {}},
        {"contact.friction", {}},
        {"gravity.acceleration", {}},
        {"analysis.dt", {}},
        {"analysis.t_end", {}}}},
      {"rolling-pipe",
       {{"pipe.length", {}},
        {"pipe.diameter", {}},
        {"pipe.inner_diameter", {}},
        {"roll.speed", {}},
        {"roll.distance", {}},
        {"texture.rms", {}},
        {"contact.friction", {}},
        {"contact.penalty_normal", {}},
        {"analysis.dt", "2.5e-5"},
        {"sensors.positions", {}}}},
      {"stiffness",
       {{"ball.radius", {}},
        {"ball.density", {}},
        {"ball.youngs_modulus", {}},
        {"flat.youngs_modulus", {}},
        {"texture.rms", {}},
        {"texture.hurst", {}},
        {"stiffness.approach_max", {}},
        {"stiffness.realisations", {}},
        {"surface.nx", {}},
        {"surface.spacing", {}}}},
      {"texture",
       {{"texture.source", {}},
        {"texture.rms", {}},
        {"texture.hurst", {}},
        {"texture.rolloff_wavelength", {}},
        {"texture.short_wavelength", {}},
        {"lines.count", {}},
        {"lines.length", {}},
        {"lines.spacing", "5e-6"},
        {"surface.count", {}}}},
  };
  return table;
}
}  // namespace

std::vector<FirstKey> first_keys(const std::string& scene) {
  std::vector<FirstKey> keys = {
      {"study.scene", scene},
      {"study.description", scene + " study written by rollspec init"},
      {"study.realisations", "100"},
      {"study.seed", "1"},
  };
  const auto it = scene_first_keys().find(scene);
  if (it != scene_first_keys().end()) keys.insert(keys.end(), it->second.begin(), it->second.end());
  return keys;
}

}  // namespace rollspec::cli
