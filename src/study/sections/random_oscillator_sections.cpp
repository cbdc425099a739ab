#include "src/study/sections/random_oscillator_sections.hpp"

#include <cmath>
#include <string>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<OscillatorSection> OscillatorSection::declare() {
  using T = OscillatorSection;
  return SectionKeys<T>("oscillator")
      .real("mass", &T::mass, "kg", "oscillator mass m", "1", above(0.0))
      .real("natural_frequency", &T::natural_frequency, "Hz", "undamped natural frequency f_n", std::nullopt,
            above(0.0))
      .real("damping_ratio", &T::damping_ratio, "-", "viscous damping ratio zeta", "0.02", {0.0, 10.0, false});
}
template struct DeclaredSection<OscillatorSection>;

SectionKeys<ForceSection> ForceSection::declare() {
  using T = ForceSection;
  return SectionKeys<T>("force")
      .choice("spectrum", &T::spectrum, "force PSD shape", ForceSpectrum::flat, kForceSpectra)
      .real("level", &T::level, "N^2/Hz", "one-sided force PSD S_F of the flat spectrum", "1", above(0.0))
      .real("f_max", &T::f_max, "Hz", "highest force frequency; 0 means the Nyquist frequency", "0", at_least(0.0))
      .choice("amplitudes", &T::amplitudes, "harmonic amplitudes", spectral::Amplitudes::rayleigh, kAmplitudes);
}
template struct DeclaredSection<ForceSection>;

SectionKeys<RecordSignalSection> RecordSignalSection::declare() {
  using T = RecordSignalSection;
  return SectionKeys<T>("signal")
      .real("sample_rate", &T::sample_rate, "Hz", "sample rate f_s of force and response", "2048", above(0.0))
      .real("duration", &T::duration, "s", "length of one realisation's record (the force's period)", "32", above(0.0));
}
template struct DeclaredSection<RecordSignalSection>;

void RecordSignalSection::finish() {
  const double n = std::round(duration * sample_rate / 2.0) * 2.0;
  if (n < 4 || n > 1e9)
    origin(duration).refuse("gives " + std::to_string(n) + " samples at the sample rate; allowed: 4 to 1e9 samples");
  samples = static_cast<std::size_t>(n);
}

}  // namespace rollspec::study
