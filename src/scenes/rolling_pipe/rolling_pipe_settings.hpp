#pragma once
// Scene `rolling-pipe`'s study keys and their reading, once, into one value with the checks that
// span several keys (the step against the contact oscillation, the record against the Welch
// segment, the surface grid against the rolled strip, the roughness curvature against the node
// spheres). The scene (rolling_pipe.cpp) builds from this value; the texture and surface
// generators read [texture] and [surface] themselves (texture_keys).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/psd.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

std::vector<study::KeySpec> rolling_pipe_keys();

struct RollingPipeSettings {
  std::uint64_t seed = 0;
  texture::Psd psd;
  study::TextureSection texture;            // [texture]: the PSD's source and amplitudes
  study::SurfaceSection surface;            // [surface]: the isotropic floor (line = false)
  texture_io::LineGeneratorKeys line_keys;  // the line's amplitudes; errors at [roughness] spacing
  bool line = true;                         // line texture (else an isotropic surface per realisation)
  double spacing = 0.0;                     // roughness (or surface) sample spacing, m
  std::size_t line_samples = 0;             // line texture samples over the rolled strip (line only)
  double x_lo = 0.0, x_hi = 0.0;            // the rolled strip along x, m
  double rms_curvature = 0.0;               // sqrt(m4) of the PSD over the sampled band, 1/m
  // Tube.
  double radius = 0.0, length = 0.0;
  int elements = 1;
  rolling::BeamSection section;
  // Roll and time stepping.
  double speed = 0.0, distance = 0.0, dt = 0.0, gravity = 0.0;
  std::size_t steps = 0, samples = 0, skip = 0;
  rolling::SolverOptions solver;
  // Contact: one law, the damper per node from its lumped mass.
  rolling::SurfaceContactLaw law;
  double damping_ratio = 0.0;
  std::vector<double> node_damping;  // N s/m
  // Sensors (nearest nodes) and spectra.
  std::vector<int> sensor_nodes;
  std::vector<double> sensor_fractions;
  bool sensor_mean = true;
  spectral::WelchConfig welch;
  double confidence = 0.95, band_min = 0.0, band_max = 0.0;

  int nodes() const { return 2 * elements + 1; }
};

RollingPipeSettings read_rolling_pipe_settings(const study::KeyReader& s);

}  // namespace rollspec::scenes
