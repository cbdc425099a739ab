#pragma once
// Default ball-on-beam integrator, README Eq. (B23)–(B26). Over a step of length h:
//  - every mode is propagated exactly (ExactOscillatorStep, first-order hold) for the modal force
//    g_n(t) = -phi_n(xi(t)) F_c(t) / m taken linear between the step ends (B23);
//  - the ball is propagated exactly for a force linear over the step (B24);
//  - the end state is then affine in the end force F1, so delta(F1) = delta_free - C F1 and
//    delta_dot(F1) = rate_free - D F1, and F1 solves the scalar contact law implicitly (B21).
// Design order: 2 in h (the only approximation is the linear interpolation of g_n over a step).
// Mode shapes at the step positions, the step coefficients and C, D are computed once per plan,
// so run() costs O(N) per step and is thread-safe (const, scratch on the stack/heap per call).
#include <utility>
#include <vector>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/integrators/exact_oscillator_step.hpp"
#include "kernels/beam/quadratic_hold_step.hpp"

namespace rollspec::beam {

// How the modal force and the ball force vary over a step: linear between the step ends (B23,
// order 2), or the parabola through the previous, current and end values (B36, order 3; the first
// step is linear; the default, as the study key [signal] hold). Both keep the end state affine in
// the end force.
enum class ForceHold { linear, quadratic };

struct ExactStepOptions {
  int substeps = 4;  // integration steps per output sample
  ForceHold hold = ForceHold::quadratic;
  double solver_tolerance = 1e-13;     // relative, contact force (B21)
  long max_table_entries = 8'000'000;  // tabulate shapes if steps * modes <= this
};

class ExactStepIntegrator {
 public:
  // substeps integration steps per output sample (h = 1 / (sample_rate * substeps)).
  // Mode shapes are tabulated at every step if steps * modes <= max_table_entries, else evaluated
  // on the fly (slower, same answer).
  ExactStepIntegrator(BallOnBeamModel model, const ExactStepOptions& options);
  // The linear hold (B23) at `substeps`: the second-order rule its own convergence tests measure.
  ExactStepIntegrator(BallOnBeamModel model, int substeps = 4, double solver_tolerance = 1e-13,
                      long max_table_entries = 8'000'000)
      : ExactStepIntegrator(std::move(model),
                            ExactStepOptions{substeps, ForceHold::linear, solver_tolerance, max_table_entries}) {}

  const BallOnBeamModel& model() const { return model_; }
  double step() const { return h_; }
  long steps() const { return steps_; }
  std::size_t samples() const { return samples_; }

  void run(const Realisation& realisation, BallOnBeamResult& out) const;
  BallOnBeamResult run(const Realisation& realisation) const;
  // Plain reference of run(): the step as (B23)-(B26) write it, one mode at a time, the modal sums
  // after the start force. run() computes the same step reordered (B26a) and agrees with this to
  // rounding (tests compare them).
  void run_reference(const Realisation& realisation, BallOnBeamResult& out) const;

 private:
  double position(long k) const;
  void shapes_at(long k, const double*& phi, const double*& slope, std::vector<double>& scratch_phi,
                 std::vector<double>& scratch_slope) const;

  // Per-mode step coefficients: free response a_ij, and the responses to the previous (m),
  // current (0) and end (1) modal force values; bm = cm = 0 for the linear hold.
  struct Coefficients {
    double a00, a01, a10, a11, bm, b0, b1, cm, c0, c1;
  };
  // Ball: w2 += u2 h - g h^2/2 + (am Fm + a0 F0 + a1 F1)/m2, u2 += -g h + (um Fm + u0 F0 + u1 F1)/m2.
  struct BallCoefficients {
    double am, a0, a1, um, u0, u1;
  };
  // run()'s step loop (B26a): one body, compiled for baseline x86-64 and for AVX2 (no FMA, so
  // both give the same bits; the AVX2 form is used where the CPU has it).
  struct LoopState;
  void steps(LoopState& st) const;
  void steps_body(LoopState& st) const;
  void steps_plain(LoopState& st) const;
#if defined(__x86_64__) && defined(__GNUC__)
  __attribute__((target("avx2"))) void steps_avx2(LoopState& st) const;
#endif
  // Per-mode step coefficients side by side (structure of arrays, padded with zeros to a multiple
  // of 4 modes) for one step kind, and the fold of the previous step's end force into this step's
  // free part (B26a): P = a00 b1' + a01 c1' + b0, Q = a10 b1' + a11 c1' + c0 (b1', c1' of the
  // previous step; zero before the first step, whose start state is given).
  struct ModeLanes {
    std::vector<double> a00, a01, a10, a11, bm, cm, b1, c1, p, q;
  };
  static ModeLanes lanes(const std::vector<Coefficients>& cur, const std::vector<Coefficients>* prev, int padded);
  const ModeLanes& lanes_of_step(long k) const { return lanes_[k < 2 ? k : 2]; }
  // The start force's share of the free sums at step k (B26a): -sum w_n P_n phi_n(xi_k) / m for
  // w = phi(xi_{k+1}) (fold_w), with Q (fold_v), and w = phi'(xi_{k+1}) (fold_s).
  // The state one output sample records: shapes at the position, modal coordinates and rates, force,
  // position, compression, roughness there, ball displacement and whether the contact is closed.
  struct SampleState {
    const double *phi, *q, *dq;
    double f, xi, delta, hx, w2;
    bool contact;
  };
  // Sample j of `out` (sensor accelerations from the exact q'' of D-9, and the contact's outputs): the
  // reference loop and the fast loop's start write it alike.
  void record_sample(BallOnBeamResult& out, std::size_t j, const SampleState& x) const;
  void fold(long k, const double* phi0, const double* phi1, const double* slope1, double& fw, double& fv,
            double& fs) const;

  void compliance(const double* phi, const double* slope, double residual, const std::vector<Coefficients>& c,
                  const BallCoefficients& bc, double& comp, double& rate, double& conv) const;

  BallOnBeamModel model_;
  ContactModel contact_;
  int substeps_;
  ForceHold hold_;
  double tol_, h_;
  long steps_;
  std::size_t samples_;
  bool total_rate_;
  std::vector<Coefficients> coef_, first_;  // hold of every step; linear hold of the first step
  BallCoefficients ball_, ball_first_;
  int padded_;                                                   // modes rounded up to a multiple of 4
  ModeLanes lanes_[3];                                           // step 0, step 1, steps >= 2
  std::vector<double> zeta_omega2_, omega2_;                     // 2 zeta_n omega_n, omega_n^2, padded
  std::vector<double> phi_table_, slope_table_;                  // [k * padded + n], empty when evaluated on the fly
  std::vector<double> fold_w_, fold_v_, fold_s_;                 // per step (B26a), empty when evaluated on the fly
  std::vector<double> comp_, rate_comp_, conv_comp_, residual_;  // C, D parts per step position
  std::vector<double> sensor_phi_;                               // [s * padded + n]
};

}  // namespace rollspec::beam
