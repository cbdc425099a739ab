#pragma once
// The Welch estimator a study's [spectrum] keys describe (segment, overlap, window), shared by the
// ensemble scenes; the sample rate comes from the scene. The keys are read by SpectrumSection.
#include <cstddef>
#include <string>

#include "kernels/spectral/welch.hpp"
#include "src/study/sections/spectrum_section.hpp"

namespace rollspec::scenes {

inline spectral::WelchConfig study_welch_config(const study::SpectrumSection& sp, double sample_rate) {
  return sp.welch_config(sample_rate);
}

// The record a scene analyses: its first `skip` of `samples` left out ([spectrum] skip_start), refused
// naming the key where nothing is left or less than one segment; `length_rule` says how the scene's keys
// set the record's length (for the message).
inline void check_analysed_record(const study::SpectrumSection& sp, std::size_t samples, std::size_t skip,
                                  const std::string& length_rule) {
  if (skip >= samples)
    sp.origin(sp.skip_start).refuse("leaves nothing of the record (" + std::to_string(samples) + " samples)");
  if (static_cast<std::size_t>(sp.segment) > samples - skip)
    sp.origin(sp.segment)
        .refuse("is longer than the analysed record (" + std::to_string(samples - skip) + " samples = " + length_rule +
                ")");
}

}  // namespace rollspec::scenes
