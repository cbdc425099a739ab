#include "src/scenes/random_oscillator/random_oscillator_settings.hpp"

#include <string>

#include "src/scenes/random_oscillator/random_oscillator.hpp"
#include "src/scenes/study_welch.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/spectrum_section.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> random_oscillator_keys() {
  return joined_keys({OscillatorSection::keys(), ForceSection::keys(), RecordSignalSection::keys()});
}

RandomOscillatorSettings read_random_oscillator_settings(const KeyReader& s) {
  RandomOscillatorSettings o;
  o.seed = StudySection::parse(s).seed;
  const auto oscillator = OscillatorSection::parse(s);
  o.mass = oscillator.mass;
  o.natural_frequency = oscillator.natural_frequency;
  o.damping_ratio = oscillator.damping_ratio;
  const auto force = ForceSection::parse(s);
  o.amplitudes = force.amplitudes;
  o.level = force.level;
  const study::SpectrumSection spectrum = study::SpectrumSection::parse(s);
  o.confidence = spectrum.confidence;
  o.band_min = spectrum.band_min;
  o.band_max = spectrum.band_max;
  // Cross-key checks, each naming the key that must change.
  const auto signal = RecordSignalSection::parse(s);
  const double fs = signal.sample_rate;
  o.sample_rate = fs;
  o.samples = signal.samples;
  if (o.natural_frequency >= fs / 2)
    oscillator.origin(oscillator.natural_frequency)
        .refuse("must lie below the Nyquist frequency f_s/2 = " + std::to_string(fs / 2) + " Hz");
  o.f_max = force.f_max == 0.0 ? fs / 2 : force.f_max;
  if (o.f_max > fs / 2)
    force.origin(force.f_max).refuse("exceeds the Nyquist frequency f_s/2 = " + std::to_string(fs / 2) + " Hz");
  const auto segment = static_cast<std::size_t>(spectrum.segment);
  if (segment > o.samples)
    spectrum.origin(spectrum.segment)
        .refuse("is longer than one realisation's record (" + std::to_string(o.samples) +
                " samples = duration x sample_rate)");
  o.welch = study_welch_config(spectrum, fs);
  return o;
}

std::vector<FirstKey> random_oscillator_first_keys() {
  return {first_key(&OscillatorSection::mass),
          first_key(&OscillatorSection::natural_frequency, "50"),
          first_key(&OscillatorSection::damping_ratio),
          first_key(&ForceSection::spectrum),
          first_key(&ForceSection::level),
          first_key(&RecordSignalSection::sample_rate),
          first_key(&RecordSignalSection::duration),
          first_key(&SpectrumSection::segment),
          first_key(&SpectrumSection::band_min),
          first_key(&SpectrumSection::band_max, "800")};
}

}  // namespace rollspec::scenes
