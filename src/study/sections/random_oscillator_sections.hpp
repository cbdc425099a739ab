#pragma once
// The sections of scene random-oscillator, read once: the [oscillator], the random [force] and the
// record ([signal]: sample rate and duration). The record's length in samples is checked here; the
// frequencies against Nyquist by the scene, at the kept origins.
#include <cstddef>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/amplitudes_choice.hpp"
#include "src/study/sections/keyed_section.hpp"

namespace rollspec::study {

class KeyReader;

struct OscillatorSection : KeyedSection {
  double mass = 1.0, natural_frequency = 0.0, damping_ratio = 0.0;

  static std::vector<KeySpec> keys();
  static OscillatorSection parse(const KeyReader& s);
};

enum class ForceSpectrum { flat };

inline constexpr ChoiceTable<ForceSpectrum, 1> kForceSpectra{{
    {ForceSpectrum::flat, "flat", "up to f_max"},
}};

struct ForceSection : KeyedSection {
  ForceSpectrum spectrum = ForceSpectrum::flat;
  double level = 0.0, f_max = 0.0;  // f_max 0: the Nyquist frequency
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;

  static std::vector<KeySpec> keys();
  static ForceSection parse(const KeyReader& s);
};

// [signal] of random-oscillator (ball-on-beam's SignalSection has other keys).
struct RecordSignalSection : KeyedSection {
  double sample_rate = 0.0, duration = 0.0;
  std::size_t samples = 0;  // duration x sample_rate rounded to even, 4 to 1e9

  static std::vector<KeySpec> keys();
  static RecordSignalSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
