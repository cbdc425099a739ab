#pragma once
// The Welch estimator a study's [spectrum] keys describe (segment, overlap, window), shared by the
// ensemble scenes; the sample rate comes from the scene.
#include <cmath>
#include <cstddef>

#include "kernels/spectral/welch.hpp"
#include "src/study/study.hpp"

namespace rollspec::scenes {

inline spectral::WelchConfig study_welch_config(const study::Study& s, double sample_rate) {
  spectral::WelchConfig wc;
  wc.sample_rate = sample_rate;
  wc.segment = static_cast<std::size_t>(s.integer("spectrum.segment"));
  wc.overlap = static_cast<std::size_t>(std::floor(s.real("spectrum.overlap") * static_cast<double>(wc.segment)));
  wc.window = s.text("spectrum.window") == "hann" ? spectral::Window::hann : spectral::Window::rectangular;
  return wc;
}

}  // namespace rollspec::scenes
