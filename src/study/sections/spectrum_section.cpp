#include "src/study/sections/spectrum_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernels/spectral/third_octave_bands.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> SpectrumSection::keys() {
  return {
      integer_key("spectrum", "segment", "Welch segment length in samples", std::string("4096"), 16, 1 << 24),
      real_key("spectrum", "overlap", "-", "Welch segment overlap as a fraction of the segment", std::string("0.5"),
               0.0, 0.95),
      choice_key("spectrum", "window", "Welch data window", spectral::Window::hann, kWelchWindows),
      real_key("spectrum", "band_min", "Hz", "lowest third-octave band edge reported", std::string("10"), 0.0, 1e9,
               false),
      real_key("spectrum", "band_max", "Hz", "highest third-octave band edge reported (capped at Nyquist)",
               std::string("1e9"), 0.0, 1e9, false),
      real_key("spectrum", "confidence", "-", "confidence level of the chi-square interval", std::string("0.95"), 0.5,
               0.999),
  };
}

SpectrumSection SpectrumSection::parse(const KeyReader& s) {
  SpectrumSection p;
  p.segment = s.integer("spectrum.segment");
  p.overlap = s.real("spectrum.overlap");
  p.window = read_choice(s, "spectrum.window", kWelchWindows);
  p.band_min = s.real("spectrum.band_min");
  p.band_max = s.real("spectrum.band_max");
  p.band_min_text = s.text("spectrum.band_min");
  p.confidence = s.real("spectrum.confidence");
  p.segment_origin = {s.where("spectrum.segment")};
  p.band_min_origin = {s.where("spectrum.band_min")};
  p.band_max_origin = {s.where("spectrum.band_max")};
  if (s.has("spectrum.skip_start")) {
    p.skip_start = s.real("spectrum.skip_start");
    p.skip_start_origin = {s.where("spectrum.skip_start")};
  }
  return p;
}

void SpectrumSection::check_band_range(double sample_rate, std::size_t segment_samples) const {
  const double df = sample_rate / static_cast<double>(segment_samples), nyquist = sample_rate / 2.0;
  const double lo = std::max(band_min, df), hi = std::min(band_max, nyquist);
  char range[200];
  std::snprintf(range, sizeof range,
                "frequency step %.6g Hz, Nyquist frequency %.6g Hz (sample rate %.6g Hz, segment %zu)", df, nyquist,
                sample_rate, segment_samples);
  if (band_max <= band_min)
    band_max_origin.refuse("not above [spectrum] band_min = " + band_min_text + "; allowed: band_min < band_max");
  if (!(hi > lo) || spectral::third_octave_bands(lo, hi).empty())
    (band_min >= nyquist ? band_min_origin : band_max_origin)
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
