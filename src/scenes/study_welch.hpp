#pragma once
// The Welch estimator a study's [spectrum] keys describe (segment, overlap, window), shared by the
// ensemble scenes; the sample rate comes from the scene.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/study/study.hpp"

namespace rollspec::scenes {

// Refuses, before any work, a [spectrum] band_min / band_max range that holds no whole third-octave
// band between the frequency step and the Nyquist frequency of the scene's sample rate.
inline void check_band_range(const study::Study& s, double sample_rate, std::size_t segment) {
  const double df = sample_rate / static_cast<double>(segment), nyquist = sample_rate / 2.0;
  const double lo = std::max(s.real("spectrum.band_min"), df), hi = std::min(s.real("spectrum.band_max"), nyquist);
  char range[200];
  std::snprintf(range, sizeof range, "frequency step %.6g Hz, Nyquist frequency %.6g Hz (sample rate %.6g Hz, segment %zu)",
                df, nyquist, sample_rate, segment);
  if (s.real("spectrum.band_max") <= s.real("spectrum.band_min"))
    s.refuse("spectrum.band_max", "not above [spectrum] band_min = " + s.text("spectrum.band_min") +
                                      "; allowed: band_min < band_max");
  if (!(hi > lo) || spectral::third_octave_bands(lo, hi).empty())
    s.refuse(s.real("spectrum.band_min") >= nyquist ? "spectrum.band_min" : "spectrum.band_max",
             std::string("no whole third-octave band fits between band_min, band_max, the ") + range +
                 "; allowed: a range holding at least one band between the frequency step and Nyquist");
}

inline spectral::WelchConfig study_welch_config(const study::Study& s, double sample_rate) {
  spectral::WelchConfig wc;
  wc.sample_rate = sample_rate;
  wc.segment = static_cast<std::size_t>(s.integer("spectrum.segment"));
  wc.overlap = static_cast<std::size_t>(std::floor(s.real("spectrum.overlap") * static_cast<double>(wc.segment)));
  wc.window = s.text("spectrum.window") == "hann" ? spectral::Window::hann : spectral::Window::rectangular;
  check_band_range(s, sample_rate, wc.segment);
  return wc;
}

}  // namespace rollspec::scenes
