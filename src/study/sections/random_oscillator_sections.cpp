#include "src/study/sections/random_oscillator_sections.hpp"

#include <cmath>
#include <string>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {

const SectionKeys<OscillatorSection>& oscillator_keys() {
  using T = OscillatorSection;
  static const auto k =
      SectionKeys<T>("oscillator")
          .real("mass", &T::mass, "kg", "oscillator mass m", "1", above(0.0))
          .real("natural_frequency", &T::natural_frequency, "Hz", "undamped natural frequency f_n", std::nullopt,
                above(0.0))
          .real("damping_ratio", &T::damping_ratio, "-", "viscous damping ratio zeta", "0.02", {0.0, 10.0, false});
  return k;
}

const SectionKeys<ForceSection>& force_keys() {
  using T = ForceSection;
  static const auto k =
      SectionKeys<T>("force")
          .choice("spectrum", &T::spectrum, "force PSD shape", ForceSpectrum::flat, kForceSpectra)
          .real("level", &T::level, "N^2/Hz", "one-sided force PSD S_F of the flat spectrum", "1", above(0.0))
          .real("f_max", &T::f_max, "Hz", "highest force frequency; 0 means the Nyquist frequency", "0", at_least(0.0))
          .choice("amplitudes", &T::amplitudes, "harmonic amplitudes", spectral::Amplitudes::rayleigh, kAmplitudes);
  return k;
}

const SectionKeys<RecordSignalSection>& record_keys() {
  using T = RecordSignalSection;
  static const auto k =
      SectionKeys<T>("signal")
          .real("sample_rate", &T::sample_rate, "Hz", "sample rate f_s of force and response", "2048", above(0.0))
          .real("duration", &T::duration, "s", "length of one realisation's record (the force's period)", "32",
                above(0.0));
  return k;
}

}  // namespace

std::vector<KeySpec> OscillatorSection::keys() { return oscillator_keys().keys(); }
OscillatorSection OscillatorSection::parse(const KeyReader& s) { return oscillator_keys().read(s); }

std::vector<KeySpec> ForceSection::keys() { return force_keys().keys(); }
ForceSection ForceSection::parse(const KeyReader& s) { return force_keys().read(s); }

std::vector<KeySpec> RecordSignalSection::keys() { return record_keys().keys(); }

RecordSignalSection RecordSignalSection::parse(const KeyReader& s) {
  RecordSignalSection r = record_keys().read(s);
  const double samples = std::round(r.duration * r.sample_rate / 2.0) * 2.0;
  if (samples < 4 || samples > 1e9)
    r.origin(r.duration)
        .refuse("gives " + std::to_string(samples) + " samples at the sample rate; allowed: 4 to 1e9 samples");
  r.samples = static_cast<std::size_t>(samples);
  return r;
}

}  // namespace rollspec::study
