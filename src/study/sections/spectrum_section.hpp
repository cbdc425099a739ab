#pragma once
// [spectrum], shared by the ensemble scenes: the Welch estimator (segment, overlap, window), the
// reported band range and the confidence level, read once. skip_start is a key of the scenes that
// have it (0 where the scene has none). The sample rate comes from the scene.
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/spectral/welch.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

inline constexpr ChoiceTable<spectral::Window, 2> kWelchWindows{{
    {spectral::Window::hann, "hann", ""},
    {spectral::Window::rectangular, "rectangular", ""},
}};

struct SpectrumSection : DeclaredSection<SpectrumSection> {
  long long segment = 0;
  double overlap = 0.0, band_min = 0.0, band_max = 0.0, confidence = 0.0, skip_start = 0.0;
  spectral::Window window = spectral::Window::hann;

  // skip_start with the doc and default of a scene that has it.
  static KeySpec skip_start_key(const std::string& doc, const std::string& fallback);
  static SectionKeys<SpectrumSection> declare();  // keys(): not skip_start (its doc is the scene's)

  // Refuses, before any work, a band_min / band_max range that holds no whole third-octave band
  // between the frequency step and the Nyquist frequency of the scene's sample rate.
  void check_band_range(double sample_rate, std::size_t segment_samples) const;
  // The Welch estimator at the scene's sample rate, the band range checked.
  spectral::WelchConfig welch_config(double sample_rate) const;
};

}  // namespace rollspec::study
