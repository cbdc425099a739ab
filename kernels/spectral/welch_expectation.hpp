#pragma once
// Expected value of the Welch estimate for a stationary process with one-sided PSD S (D-20):
//
//   E[P_k] = int_0^{f_s/2} S(f) [K(f_k - f) + K(f_k + f)] df,
//   K(nu) = |sum_i w_i e^{-2 pi i nu i / f_s}|^2 / (f_s sum_i w_i^2)     (int K over one period = 1)
//
// (the one-sided form folds the negative frequencies back; aliasing from beyond f_s/2 is
// neglected). A Welch estimate converges to this, not to S, when S varies within a few bins
// (resonance peaks narrower than the window's bandwidth), so Monte-Carlo checks compare with it.
// S is given on the fine grid f_j = j df / M, j = 0..M (n_freq - 1); K is evaluated exactly on that
// grid by one FFT of the window zero-padded to M L.
#include <cstddef>
#include <vector>

#include "kernels/spectral/welch.hpp"

namespace rollspec::spectral {

// fine_psd.size() must be refine * (plan.n_freq() - 1) + 1. Returns n_freq values.
std::vector<double> welch_expectation(const WelchPlan& plan, const std::vector<double>& fine_psd, std::size_t refine);

// Plain O(n_freq * n_fine * L) evaluation of the same integral (reference oracle for tests).
std::vector<double> welch_expectation_direct(const WelchPlan& plan, const std::vector<double>& fine_psd,
                                             std::size_t refine);

}  // namespace rollspec::spectral
