#pragma once
// The harmonic amplitudes of a synthesised random line or force ([texture] amplitudes,
// [force] amplitudes): one table for both keys.
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::study {

inline constexpr ChoiceTable<spectral::Amplitudes, 2> kAmplitudes{{
    {spectral::Amplitudes::rayleigh, "rayleigh", "Gaussian"},
    {spectral::Amplitudes::deterministic, "deterministic", "the target PSD exactly"},
}};

}  // namespace rollspec::study
