#pragma once
// The step loop's shared pieces (internal to kernels/beam): the four-lane mode vectors of
// exact_step_integrator.cpp and exact_step_loop.cpp, and the state run() hands to the loop.
#include <cstring>
#include <vector>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/exact_step_integrator.hpp"

namespace rollspec::beam::detail {

// Modes n, n+1, n+2, n+3 as one value (padded to a multiple of 4 with zero modes): GCC's vector
// extension gives AVX2 registers in the AVX2 build of the step loop and pairs of SSE2 registers
// in the plain one, the same element-wise operations (no FMA) and so the same bits. Sums over
// the modes run in the four lanes (n mod 4), combined as (l0 + l2) + (l1 + l3): one order for
// every build, and four short dependency chains instead of one. Passed by reference only (a
// by-value 32-byte vector changes the ABI).
using Lanes = double __attribute__((vector_size(32)));

__attribute__((always_inline)) inline void load(Lanes& v, const double* p) { std::memcpy(&v, p, sizeof v); }
__attribute__((always_inline)) inline void store(double* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }
__attribute__((always_inline)) inline double lane_sum(const Lanes& v) { return (v[0] + v[2]) + (v[1] + v[3]); }

// sum_n a_n (b_n c_n) in the same lanes and order as the step loop's sums.
inline double lane_dot3(const double* a, const double* b, const double* c, int np) {
  double l0 = 0.0, l1 = 0.0, l2 = 0.0, l3 = 0.0;
  for (int i = 0; i < np; i += 4) {
    l0 += a[i] * (b[i] * c[i]);
    l1 += a[i + 1] * (b[i + 1] * c[i + 1]);
    l2 += a[i + 2] * (b[i + 2] * c[i + 2]);
    l3 += a[i + 3] * (b[i + 3] * c[i + 3]);
  }
  return (l0 + l2) + (l1 + l3);
}

}  // namespace rollspec::beam::detail

namespace rollspec::beam {

// run() = run_reference() with the step reordered (README B26a). The state carried from step to
// step is the free part (qf, vf) of the last step and its start force g0 = -phi(xi_k) F_k / m,
// not the end state q = qf + b1 g1: the next step's free part is then
//   qf' = [a00 qf + a01 vf + bm g0] + P g1,  vf' = [a10 qf + a11 vf + cm g0] + Q g1   (B26a)
// with P, Q from the coefficients of both steps (lanes()). The bracket waits for no contact solve,
// and the sums sum phi(xi_{k+2}) qf' that the next solve needs are the bracket's sum plus
// F_{k+1} times a per-step number (fold()): the chain from one contact force to the next is a
// few scalar operations, not a sum over the modes. One pass over the modes per step, after the
// solve: this step's free part, its output (every substeps-th step) and the next step's bracket.
struct ExactStepIntegrator::LoopState {
  const Realisation* r;
  BallOnBeamResult* out;
  const PatchAverager* averager;
  std::vector<double> x, y, u, zeros;  // padded: the bracket of the coming step, outputs, zero slopes
  std::vector<double> ring;            // shapes evaluated on the fly: 3 positions x (phi, slope), padded
  double w2, u2, f, f_prev, delta_last;
  long lost = 0;
};

}  // namespace rollspec::beam
