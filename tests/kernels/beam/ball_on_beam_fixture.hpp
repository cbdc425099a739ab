#pragma once
// A seed-002-like rig for the ball-on-beam tests: clamped–clamped 6 x 50 mm steel, span 0.39 m in
// an effective length of 0.42 m, 40 mm steel ball, smooth deterministic roughness.
#include <cmath>
#include <vector>

#include "kernels/beam/ball_on_beam.hpp"

namespace rollspec::beam::test {

inline BeamProperties rig_beam() {
  BeamProperties p;
  p.length = 0.39;
  p.effective_length = 0.42;
  return p;
}

// Sum of sinusoids h(x) = sum a_i sin(2 pi x / lambda_i + phase_i), sampled every dx over [0, l].
inline UniformSamples sine_roughness(double length, double dx, const std::vector<double>& amplitude,
                                     const std::vector<double>& wavelength) {
  UniformSamples s;
  s.origin = 0.0;
  s.step = dx;
  const std::size_t n = static_cast<std::size_t>(std::ceil(length / dx)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) * dx;
    double h = 0.0;
    for (std::size_t j = 0; j < amplitude.size(); ++j)
      h += amplitude[j] * std::sin(6.283185307179586 * x / wavelength[j] + 0.7 * static_cast<double>(j));
    s.values.push_back(h);
  }
  return s;
}

inline BallOnBeamModel hertz_model(int modes, double x_start, double x_end, double sample_rate) {
  BallOnBeamModel m{ModalBeam(rig_beam(), {modes, 0.0}, {0.02, {}}), Ball{}, ContactLaw{}, Traverse{}, sample_rate, {}};
  m.contact.kind = ContactLawKind::hertz;
  m.contact.damping = 100.0;
  m.traverse = {x_start, x_end, 1.0, 0.0};
  m.sensors = {0.05, 0.13, 0.195, 0.26, 0.33};
  return m;
}

}  // namespace rollspec::beam::test
