#include "src/scenes/random_oscillator_settings.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "src/scenes/study_welch.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> random_oscillator_keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      real_key("oscillator", "mass", "kg", "oscillator mass m", std::string("1"), 0.0, inf, false),
      real_key("oscillator", "natural_frequency", "Hz", "undamped natural frequency f_n", std::nullopt, 0.0, inf,
               false),
      real_key("oscillator", "damping_ratio", "-", "viscous damping ratio zeta", std::string("0.02"), 0.0, 10.0, false),
      choice_key("force", "spectrum", "force PSD shape: flat up to f_max", std::string("flat"), {"flat"}),
      real_key("force", "level", "N^2/Hz", "one-sided force PSD S_F of the flat spectrum", std::string("1"), 0.0, inf,
               false),
      real_key("force", "f_max", "Hz", "highest force frequency; 0 means the Nyquist frequency", std::string("0"), 0.0,
               inf),
      choice_key("force", "amplitudes",
                 "harmonic amplitudes: rayleigh (Gaussian force) or deterministic (the target PSD exactly)",
                 std::string("rayleigh"), {"rayleigh", "deterministic"}),
      real_key("signal", "sample_rate", "Hz", "sample rate f_s of force and response", std::string("2048"), 0.0, inf,
               false),
      real_key("signal", "duration", "s", "length of one realisation's record (the force's period)", std::string("32"),
               0.0, inf, false),
  };
}

RandomOscillatorSettings read_random_oscillator_settings(const KeyReader& s) {
  RandomOscillatorSettings o;
  o.seed = static_cast<std::uint64_t>(s.integer("study.seed"));
  o.mass = s.real("oscillator.mass");
  o.natural_frequency = s.real("oscillator.natural_frequency");
  o.damping_ratio = s.real("oscillator.damping_ratio");
  o.sample_rate = s.real("signal.sample_rate");
  o.amplitudes =
      s.text("force.amplitudes") == "rayleigh" ? spectral::Amplitudes::rayleigh : spectral::Amplitudes::deterministic;
  o.level = s.real("force.level");
  const study::SpectrumSection spectrum = study::SpectrumSection::parse(s);
  o.confidence = spectrum.confidence;
  o.band_min = spectrum.band_min;
  o.band_max = spectrum.band_max;
  // Cross-key checks, each naming the key that must change.
  const double fs = o.sample_rate;
  const double samples = std::round(s.real("signal.duration") * fs / 2.0) * 2.0;
  if (samples < 4 || samples > 1e9)
    s.refuse("signal.duration",
             "gives " + std::to_string(samples) + " samples at the sample rate; allowed: 4 to 1e9 samples");
  o.samples = static_cast<std::size_t>(samples);
  if (o.natural_frequency >= fs / 2)
    s.refuse("oscillator.natural_frequency",
             "must lie below the Nyquist frequency f_s/2 = " + std::to_string(fs / 2) + " Hz");
  o.f_max = s.real("force.f_max") == 0.0 ? fs / 2 : s.real("force.f_max");
  if (o.f_max > fs / 2)
    s.refuse("force.f_max", "exceeds the Nyquist frequency f_s/2 = " + std::to_string(fs / 2) + " Hz");
  const auto segment = static_cast<std::size_t>(spectrum.segment);
  if (segment > o.samples)
    spectrum.segment_origin.refuse("is longer than one realisation's record (" + std::to_string(o.samples) +
                                   " samples = duration x sample_rate)");
  o.welch = study_welch_config(spectrum, fs);
  return o;
}

}  // namespace rollspec::scenes
