#pragma once
// The Welch estimator a study's [spectrum] keys describe (segment, overlap, window), shared by the
// ensemble scenes; the sample rate comes from the scene. The keys are read by SpectrumSection.
#include "kernels/spectral/welch.hpp"
#include "src/study/sections/spectrum_section.hpp"

namespace rollspec::scenes {

inline spectral::WelchConfig study_welch_config(const study::SpectrumSection& sp, double sample_rate) {
  return sp.welch_config(sample_rate);
}

}  // namespace rollspec::scenes
