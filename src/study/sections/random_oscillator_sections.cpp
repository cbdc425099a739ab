#include "src/study/sections/random_oscillator_sections.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<KeySpec> OscillatorSection::keys() {
  return {
      real_key("oscillator", "mass", "kg", "oscillator mass m", std::string("1"), 0.0, inf, false),
      real_key("oscillator", "natural_frequency", "Hz", "undamped natural frequency f_n", std::nullopt, 0.0, inf,
               false),
      real_key("oscillator", "damping_ratio", "-", "viscous damping ratio zeta", std::string("0.02"), 0.0, 10.0, false),
  };
}

OscillatorSection OscillatorSection::parse(const KeyReader& s) {
  OscillatorSection o;
  o.mass = s.real("oscillator.mass");
  o.natural_frequency = s.real("oscillator.natural_frequency");
  o.damping_ratio = s.real("oscillator.damping_ratio");
  o.natural_frequency_origin = {s.where("oscillator.natural_frequency")};
  return o;
}

std::vector<KeySpec> ForceSection::keys() {
  return {
      choice_key("force", "spectrum", "force PSD shape", ForceSpectrum::flat, kForceSpectra),
      real_key("force", "level", "N^2/Hz", "one-sided force PSD S_F of the flat spectrum", std::string("1"), 0.0, inf,
               false),
      real_key("force", "f_max", "Hz", "highest force frequency; 0 means the Nyquist frequency", std::string("0"), 0.0,
               inf),
      choice_key("force", "amplitudes", "harmonic amplitudes", spectral::Amplitudes::rayleigh, kAmplitudes),
  };
}

ForceSection ForceSection::parse(const KeyReader& s) {
  ForceSection f;
  f.spectrum = read_choice(s, "force.spectrum", kForceSpectra);
  f.amplitudes = read_choice(s, "force.amplitudes", kAmplitudes);
  f.level = s.real("force.level");
  f.f_max = s.real("force.f_max");
  f.f_max_origin = {s.where("force.f_max")};
  return f;
}

std::vector<KeySpec> RecordSignalSection::keys() {
  return {
      real_key("signal", "sample_rate", "Hz", "sample rate f_s of force and response", std::string("2048"), 0.0, inf,
               false),
      real_key("signal", "duration", "s", "length of one realisation's record (the force's period)", std::string("32"),
               0.0, inf, false),
  };
}

RecordSignalSection RecordSignalSection::parse(const KeyReader& s) {
  RecordSignalSection r;
  r.sample_rate = s.real("signal.sample_rate");
  r.duration = s.real("signal.duration");
  const double samples = std::round(r.duration * r.sample_rate / 2.0) * 2.0;
  if (samples < 4 || samples > 1e9)
    s.refuse("signal.duration",
             "gives " + std::to_string(samples) + " samples at the sample rate; allowed: 4 to 1e9 samples");
  r.samples = static_cast<std::size_t>(samples);
  return r;
}

}  // namespace rollspec::study
