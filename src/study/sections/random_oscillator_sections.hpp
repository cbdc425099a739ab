#pragma once
// The sections of scene random-oscillator, read once: the [oscillator], the random [force] and the
// record ([signal]: sample rate and duration). The record's length in samples is checked here; the
// frequencies against Nyquist by the scene, at the kept origins.
#include <cstddef>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/amplitudes_choice.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

struct OscillatorSection : DeclaredSection<OscillatorSection> {
  double mass = 1.0, natural_frequency = 0.0, damping_ratio = 0.0;

  static SectionKeys<OscillatorSection> declare();
};

enum class ForceSpectrum { flat };

inline constexpr ChoiceTable<ForceSpectrum, 1> kForceSpectra{{
    {ForceSpectrum::flat, "flat", "up to f_max"},
}};

struct ForceSection : DeclaredSection<ForceSection> {
  ForceSpectrum spectrum = ForceSpectrum::flat;
  double level = 0.0, f_max = 0.0;  // f_max 0: the Nyquist frequency
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;

  static SectionKeys<ForceSection> declare();
};

// [signal] of random-oscillator (ball-on-beam's SignalSection has other keys).
struct RecordSignalSection : DeclaredSection<RecordSignalSection> {
  double sample_rate = 0.0, duration = 0.0;
  std::size_t samples = 0;  // duration x sample_rate rounded to even, 4 to 1e9

  static SectionKeys<RecordSignalSection> declare();
  void finish();  // samples, checked
};

}  // namespace rollspec::study
