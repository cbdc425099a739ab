#pragma once
// Expected value of the Welch estimate for a stationary process with one-sided PSD S (D-20):
//
//   E[P_k] = int_0^{f_s/2} S(f) [K(f_k - f) + K(f_k + f)] df,
//   K(nu) = |sum_i w_i e^{-2 pi i nu i / f_s}|^2 / (f_s sum_i w_i^2)     (int K over one period = 1)
//
// (the one-sided form folds the negative frequencies back). K is periodic in f_s, so when S is
// the PSD of a continuous signal that is sampled at f_s, the same integral taken beyond f_s/2
// (to wherever S ends) is the expectation including aliasing; taken to f_s/2 only, aliasing is
// neglected. A Welch estimate converges to this, not to S, when S varies within a few bins
// (resonance peaks narrower than the window's bandwidth), so Monte-Carlo checks compare with it.
// S is given on the fine grid f_j = j df / M, j = 0..J with J >= M (n_freq - 1) (J > M (n_freq - 1):
// S continues beyond f_s/2 and aliases); K is evaluated exactly on that grid by one FFT of the
// window zero-padded to M L.
#include <complex>
#include <cstddef>
#include <vector>

#include "kernels/spectral/welch.hpp"

namespace rollspec::spectral {

// fine_psd.size() must be at least refine * (plan.n_freq() - 1) + 1; values beyond f_s/2 alias.
// Returns n_freq values.
std::vector<double> welch_expectation(const WelchPlan& plan, const std::vector<double>& fine_psd, std::size_t refine);

// Plain O(n_freq * n_fine * L) evaluation of the same integral (reference oracle for tests).
std::vector<double> welch_expectation_direct(const WelchPlan& plan, const std::vector<double>& fine_psd,
                                             std::size_t refine);

// K(m f_s / (L refine)), m = 0..L refine - 1 (periodic and even in m), as used above.
std::vector<double> welch_kernel(const WelchPlan& plan, std::size_t refine);

// Share of the Welch estimate from n samples that each sample carries (kernels/beam README
// B34a): for a locally stationary record with PSD S(t, f) the estimate's expectation is sum_t W_t E_t[S],
//   W_t = sum_a w^2(t - a S) / (N_B sum_i w_i^2)   (sums to 1; samples after the last segment: 0).
std::vector<double> welch_time_weights(const WelchPlan& plan, std::size_t n);

// Equivalent chi-square dof of the Welch estimate (from n samples) of the mean PSD over `channels`
// correlated channels of a locally stationary Gaussian record, D-16 generalised (kernels/beam
// README B34b):
//   C_ab^{ss'} = sum_p u_ab(p) S_p^{ss'},  u_ab(p) = sum_{t in block p} w(t - t_a) w(t - t_b) / sum w^2,
//   E = sum_s sum_a C_aa^{ss} / (N_B n_c),  Var = sum_{s,s'} sum_{a,b} |C_ab^{ss'}|^2 / (N_B n_c)^2,
//   nu = 2 E^2 / Var,
// with S_p^{ss'} the (window-smoothed) cross-spectra while the record is in block p = samples
// [edges[p], edges[p+1]). For one stationary channel this is equivalent_dof(n); for n_c
// uncorrelated channels of equal level n_c times it. cross[(p * pairs + q) * bins + k], q running
// over s <= s' (s outer). Returns dof per bin for one realisation.
std::vector<double> welch_block_dof(const WelchPlan& plan, std::size_t n, const std::vector<std::size_t>& edges,
                                    std::size_t channels, std::size_t bins,
                                    const std::vector<std::complex<double>>& cross);

// The same in two steps, for callers that can form C_ab themselves (linear in S_p: a caller may sum
// u_ab(p) times what it smooths into S_p before smoothing, once per (a, b) instead of once per block).
// The nonzero u_ab(p) / sum w^2, grouped by (a, b = a + m): terms of one group are consecutive, p
// ascending; groups in a-major, m-minor order.
struct WelchBlockTerms {
  struct Term {
    std::size_t group, block;
    double u;
  };
  std::vector<Term> terms;
  std::vector<std::size_t> group_m;  // m = b - a of each group
  std::size_t segments = 0;          // N_B
};
WelchBlockTerms welch_block_terms(const WelchPlan& plan, std::size_t n, const std::vector<std::size_t>& edges);
// nu per bin from the grouped cross-spectra grouped[(g * pairs + q) * bins + k] = C_ab^q[k] of group g.
std::vector<double> welch_group_dof(const WelchBlockTerms& t, std::size_t channels, std::size_t bins,
                                    const std::vector<std::complex<double>>& grouped);

}  // namespace rollspec::spectral
