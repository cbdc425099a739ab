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
  int substeps = 4;                     // integration steps per output sample
  ForceHold hold = ForceHold::quadratic;
  double solver_tolerance = 1e-13;      // relative, contact force (B21)
  long max_table_entries = 8'000'000;   // tabulate shapes if steps * modes <= this
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
      : ExactStepIntegrator(std::move(model), ExactStepOptions{substeps, ForceHold::linear, solver_tolerance,
                                                               max_table_entries}) {}

  const BallOnBeamModel& model() const { return model_; }
  double step() const { return h_; }
  long steps() const { return steps_; }
  std::size_t samples() const { return samples_; }

  void run(const Realisation& realisation, BallOnBeamResult& out) const;
  BallOnBeamResult run(const Realisation& realisation) const;

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
  std::vector<Coefficients> coef_, first_;      // hold of every step; linear hold of the first step
  BallCoefficients ball_, ball_first_;
  std::vector<double> phi_table_, slope_table_;  // [k * N + n], empty when evaluated on the fly
  std::vector<double> comp_, rate_comp_, conv_comp_, residual_;  // C, D parts per step position
  std::vector<double> sensor_phi_;              // [s * N + n]
};

}  // namespace rollspec::beam
