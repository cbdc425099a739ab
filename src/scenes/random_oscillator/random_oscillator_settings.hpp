#pragma once
// Scene `random-oscillator`'s study keys and their reading, once, into one value with the checks
// that span several keys (record length, natural and highest force frequency against Nyquist,
// Welch segment against the record).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

std::vector<study::KeySpec> random_oscillator_keys();

struct RandomOscillatorSettings {
  std::uint64_t seed = 0;
  double mass = 1.0, natural_frequency = 0.0, damping_ratio = 0.0;
  double sample_rate = 0.0;
  std::size_t samples = 0;  // per record, even: one period of the force
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;
  double level = 0.0, f_max = 0.0;  // flat one-sided force PSD up to f_max
  spectral::WelchConfig welch;
  double confidence = 0.95, band_min = 0.0, band_max = 0.0;

  double force_psd(double f) const { return (f > 0.0 && f <= f_max) ? level : 0.0; }
};

RandomOscillatorSettings read_random_oscillator_settings(const study::KeyReader& s);

}  // namespace rollspec::scenes
