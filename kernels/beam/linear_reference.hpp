#pragma once
// Frequency-domain reference of the linearised ball-on-beam Monte-Carlo (seed 002 check), made
// exact for what the time integrator simulates (README B34, B34a-c, B35a, B13; kernels/spectral D-20):
//  - excitation: the blocked-force samples the integrator sees, W + k0 (patch-averaged samples of
//    the synthesised roughness): k0^2 G_t(f) T(k)^2 with T the patch filter acting on samples
//    (B35a: sin(ka)/(ka) times the linear interpolant's sinc^2(k dx/2)), no harmonic above pi/dx,
//    times |C|^2 of the Catmull-Rom interpolation (B13) at the steps' offset from the samples;
//    or the blocked force's own PSD, synthesised at the integration step;
//  - receptances averaged over ball positions with the Welch estimate's own time weights (B34a:
//    sum over segments of the squared window), not uniformly;
//  - the PSD continues to the integration step's Nyquist frequency and aliases into [0, f_s/2]
//    when the outputs are sampled (B34c: the D-20 integral taken beyond f_s/2);
//  - then the expected Welch estimate (D-20): the window resolves no resonance narrower than a bin;
//  - the chi-square dof of the ensemble mean per bin for this non-stationary record (B34b).
// Left out: the moving load (quasi-stationary in the ball position). Its bias grows with the
// distance the ball travels while the modes respond (v / (zeta_1 omega_1) against the analysed
// length), not only with the seeds' Tf/tau (fundamental period over traverse time): measured in
// tests/cli/test_ball_on_beam.py.
#include <cstddef>
#include <functional>
#include <vector>

#include "kernels/beam/modal_beam.hpp"
#include "kernels/spectral/welch.hpp"

namespace rollspec::beam {

// |C(theta)|^2 of Catmull-Rom interpolation (B13) read at fraction tau in [0, 1) between samples
// of a sinusoid that advances theta per sample.
double catmull_rom_gain(double tau, double theta);

// The blocked force F0 the integrator is driven by (D-11).
struct ReferenceExcitation {
  // One-sided PSD in time at f (Hz): of the roughness under the moving ball, m^2/Hz
  // (F0 = W + k0 h_patch), or with blocked_force, of F0 itself, N^2/Hz.
  std::function<double(double)> time_psd;
  bool blocked_force = false;     // F0 synthesised at the integration step up to its Nyquist frequency
  double k0 = 0.0;                // linearised contact stiffness, N/m
  double speed = 0.0;             // v, m/s
  double spacing = 0.0;           // dx of the roughness samples, m
  double patch_half_width = 0.0;  // a of the contact-patch filter, m (0: none)
  double x_start = 0.0;           // ball position at the start of the record, m
  double step = 0.0;              // integration step, s
};

// PSD of the excitation the integrator sees at each frequency (0 at f = 0).
std::vector<double> reference_excitation(const ReferenceExcitation& e, const std::vector<double>& frequencies);

// Ball positions with the Welch time weights of the analysed record (B34a): blocks of consecutive
// samples at their weighted mean position; a block's weight sums welch_time_weights over it.
struct PositionBlocks {
  std::vector<std::size_t> edges;  // block p: analysed samples [edges[p], edges[p+1]); edges.back() = n
  std::vector<double> position, weight;
  std::size_t count() const { return position.size(); }
};
// n analysed samples starting `skip` samples into the record; ball at x_start + v t, sampled at
// sample_rate; at most max_blocks blocks.
PositionBlocks welch_position_blocks(const spectral::WelchPlan& plan, std::size_t n, std::size_t skip, double x_start,
                                     double speed, double sample_rate, std::size_t max_blocks = 256);

struct LinearReferenceInput {
  const ModalBeam* beam = nullptr;
  double ball_mass = 0.0, damping = 0.0;  // kg; contact damper c0, N s/m (k0: excitation.k0)
  std::vector<double> sensors;            // positions, m
  bool sensor_mean = false;               // add the mean over sensors as a last row
  const spectral::WelchPlan* welch = nullptr;
  double sample_rate = 0.0;  // output sample rate (the Welch plan's), Hz
  std::size_t refine = 8;    // fine frequency grid per Welch bin (D-20)
  ReferenceExcitation excitation;
  PositionBlocks positions;
  double realisations = 1.0;  // the ensemble mean's dof scale with it
  double confidence = 0.95;   // of the range [mean_lower, mean_upper]
};

// rows = sensors (+ mean), bins = Welch bins; every field rows x bins, row-major.
struct LinearReference {
  std::size_t rows = 0, bins = 0;
  std::vector<double> psd;  // expected Welch estimate (D-20) of the frequency-domain PSD
  std::vector<double> raw;  // the PSD itself at the bin frequencies
  std::vector<double> dof;  // chi-square dof of the ensemble mean per bin (B34b)
  // where the ensemble mean falls with probability `confidence` if psd is right: nu P / S ~ chi2(nu) (D-16)
  std::vector<double> mean_lower, mean_upper;
};

// Units of work linear_reference reports through its callback.
std::size_t linear_reference_steps(const LinearReferenceInput& in);
// step (optional) is called after each unit of work, for progress reports.
// The products behind the dof are summed with the Welch weights u_ab(p) before they are smoothed
// (B34b is linear in the blocks' spectra), once per segment pair instead of once per block, and
// the modal sums run over ranges of frequencies at a time: the PSD rows are those of
// linear_reference_plain to the last bit in the band, the dof to rounding.
LinearReference linear_reference(const LinearReferenceInput& in, const std::function<void()>& step = {});
// The same by the plain path, one block at a time (the reference tests compare with).
LinearReference linear_reference_plain(const LinearReferenceInput& in);

}  // namespace rollspec::beam
