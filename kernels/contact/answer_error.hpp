#pragma once
// The error of a PSD band level from a white error in the sequence it was estimated from (contact
// README BF-9c): how BF-9's measured F0 residuals reach the band levels the user reads.
//
// A sequence F of n samples at step Δx carries an error e, white, independent of F, of variance σ²: its
// one-sided PSD is S_e = 2 σ² Δx (per cycle/m; divide by 2π per rad/m). The Welch band average S̄ of F + e
// moves by E|ê|² = S_e (the bias) and by the cross term 2 Re F̂ ê*, whose relative variance is 4 S_e / (S̄ ν_b),
// ν_b the band average's equivalent degrees of freedom (kernels/spectral D-33c a: the bins' and the
// overlapping segments' correlation included). In dB,
//
//     ε_b = (10 / ln 10) · sqrt( (S_e / S̄)² + 4 S_e / (S̄ ν_b) )                              (BF-9c)
//
// The band's bins and weights are band_average's (kernels/spectral D-17). A band below bin `first_bin`
// takes that bin's error (its callers scale a shape to that bin there). Beyond the last bin, or at no
// power, NaN.
#include <cstddef>
#include <vector>

#include "kernels/spectral/welch.hpp"

namespace rollspec::contact {

// `config`: the Welch plan the PSD came from (sample_rate 1/Δx); `samples`: n; `psd`: its bins (any unit);
// `error_psd`: S_e in psd's unit; [lower, upper] in the config's frequency unit (cycles/m for 1/Δx).
double white_error_band_db(const spectral::WelchConfig& config, std::size_t samples, const std::vector<double>& psd,
                           std::size_t first_bin, double error_psd, double lower, double upper);

}  // namespace rollspec::contact
