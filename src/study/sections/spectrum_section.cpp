#include "src/study/sections/spectrum_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernels/spectral/third_octave_bands.hpp"
#include "src/study/sections/section_keys.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::study {

SectionKeys<SpectrumSection> SpectrumSection::declare() {
  using T = SpectrumSection;
  return SectionKeys<T>("spectrum")
      .integer("segment", &T::segment, "Welch segment length in samples", "4096", 16, 1 << 24)
      .real("overlap", &T::overlap, "-", "Welch segment overlap as a fraction of the segment", "0.5", within(0.0, 0.95))
      .choice("window", &T::window, "Welch data window", spectral::Window::hann, kWelchWindows)
      .real("band_min", &T::band_min, "Hz", "lowest third-octave band edge reported", "10", {0.0, 1e9, false})
      .real("band_max", &T::band_max, "Hz", "highest third-octave band edge reported (capped at Nyquist)", "1e9",
            {0.0, 1e9, false})
      .real("confidence", &T::confidence, "-", "confidence level of the chi-square interval", "0.95",
            within(0.5, 0.999))
      .real("skip_start", &T::skip_start, "s", "", "0", at_least(0.0))
      .scene_declared();
}
template struct DeclaredSection<SpectrumSection>;

KeySpec SpectrumSection::skip_start_key(const std::string& doc, const std::string& fallback) {
  KeySpec k = declared().keys_of(&SpectrumSection::skip_start)[0];
  k.doc = doc;
  k.default_value = fallback;
  return k;
}

void SpectrumSection::check_band_range(double sample_rate, std::size_t segment_samples) const {
  const double df = sample_rate / static_cast<double>(segment_samples), nyquist = sample_rate / 2.0;
  const double lo = std::max(band_min, df), hi = std::min(band_max, nyquist);
  const std::string range =
      io::formatted("frequency step %.6g Hz, Nyquist frequency %.6g Hz (sample rate %.6g Hz, segment %zu)", df, nyquist,
                    sample_rate, segment_samples);
  if (band_max <= band_min)
    origin(band_max).refuse("not above [spectrum] band_min = " + value_text(band_min) +
                            "; allowed: band_min < band_max");
  if (!(hi > lo) || spectral::third_octave_bands(lo, hi).empty())
    (band_min >= nyquist ? origin(band_min) : origin(band_max))
        .refuse(std::string("no whole third-octave band fits between band_min, band_max, the ") + range +
                "; allowed: a range holding at least one band between the frequency step and Nyquist");
}

spectral::WelchConfig SpectrumSection::welch_config(double sample_rate) const {
  spectral::WelchConfig wc;
  wc.sample_rate = sample_rate;
  wc.segment = static_cast<std::size_t>(segment);
  wc.overlap = static_cast<std::size_t>(std::floor(overlap * static_cast<double>(wc.segment)));
  wc.window = window;
  check_band_range(sample_rate, wc.segment);
  return wc;
}

}  // namespace rollspec::study
