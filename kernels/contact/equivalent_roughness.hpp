#pragma once
// Equivalent roughness of a rough strip under a ball at a fixed load (issue 19, `[contact]
// filter = solver`; kernels/contact/README.md "Equivalent roughness", Eq. ER-1 … ER-6).
//
// The ball centre moves along y = y_c through the positions ξ_k (strictly increasing by whole cells
// dx, as in blocked_force.hpp). At each position δ_eq(ξ_k) is the rigid approach, measured from the
// plane h = 0 (the strip's mean plane for zero-mean heights, BF-2), at which the half-space solve
// carries the load W:
//
//     P(δ_eq(ξ_k); ξ_k) = W                                                                (ER-1)
//
// and the equivalent roughness is
//
//     h_eq(ξ_k) = δ_smooth − δ_eq(ξ_k)                                                      (ER-2)
//
// δ_smooth: the approach for W on a flat strip on the same grid, same ball sub-cell offset (the
// discretisation error of the approach cancels). A raised surface under the ball needs less
// approach, so h_eq > 0 there: h_eq enters the point contact law δ = w1 + h − w2 (kernels/beam
// D-1, B15) exactly as the raw line h does.
//
// Fast path: the moving solver window of the blocked force (BF-5 confinement, checked at δ_eq),
// each position one load-controlled solve (ContactSolver::solve_at_force, README Eq. 17: the
// approach is the multiplier of ΔA Σ p = W, so ER-1 holds to rounding) started from the previous
// field shifted with the ball (BF-6), its cells listed from the previous δ_eq. A solve that does not
// converge is redone by the Newton on the approach of force_control.hpp from the same start.
//
// At the answer's tolerance (answer_tolerance > 0; 0, the default, is the reference above): every
// position's solve stops at max(tolerance, answer_tolerance), and every check_stride-th position, half a
// stride after each chunk's cold start (k = s/2, 3s/2, ...), is solved again from its own loose field to
// the full tolerance. The load holds at any tolerance (Eq. 17 puts Σ p on W exactly), so a loose solve
// errs in the pressure's shape and with it in δ_eq; the residuals
//
//     r_j = h_eq,full(ξ_j) − h_eq,loose(ξ_j)                                                 (ER-8)
//
// are a systematic sample of the table's error, which the table carries to its PSD's band levels as
// BF-9c does (kernels/contact/answer_error.hpp; on the seed 002 strip the error is white within a
// factor 3 over the bins, checked against the reference at every position). The tabulated h_eq stays
// the loose one everywhere, so the sample measures what the table holds.
#include <cstddef>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

struct EquivalentRoughnessOptions {
  double centre_y = 0.0;          // y_c of the path in the strip grid (m)
  double load_tolerance = 1e-10;  // |P − W| ≤ load_tolerance · W at every position
  int max_solves = 100;           // Newton's contact solves per position (reference, fast path's fallback)
  bool warm_start = true;  // BF-6 field + previous δ_eq; false: every position cold (from δ_smooth's interference)
  // Chunks of this many positions (0: one chunk, the whole path in order). Each chunk starts from
  // the flat strip's field and δ_smooth, then warm-starts along itself; chunks run in parallel
  // (OpenMP, one solver per thread). The chunk boundaries are fixed by this number alone, so the
  // result has the same bits for any thread count (ER-1 is solved to the same tolerance either way).
  std::size_t chunk_positions = 0;
  // k_eq (ER-7) at the positions k = 0, m, 2m, ... (and δ_smooth's k_s): a displacement solve at the
  // found δ_eq with the frozen-set stiffness (Eq. 11, 13–15), which the load-controlled solve does not
  // give; NaN elsewhere. 0: none. Their mean is all ER-7 needs, and one in 16 adds ~16 % to the cost.
  std::size_t stiffness_every = 16;
  // ER-8: > 0, each position's solve to max(tolerance, answer_tolerance), checked at every
  // check_stride-th position (0: no checks); 0: every solve to the full tolerance (the reference path).
  double answer_tolerance = 0.0;
  std::size_t check_stride = 16;
};

struct EquivalentRoughness {
  std::vector<double> position;       // ξ_k (m, strip coordinates)
  std::vector<double> approach;       // δ_eq(ξ_k) (m), ER-1
  std::vector<double> height;         // h_eq(ξ_k) (m), ER-2
  std::vector<double> contact_area;   // real contact area at δ_eq (m²)
  std::vector<double> plastic_cells;  // cells at the pressure cap at δ_eq
  // k_eq(ξ_k) = dP/dδ at δ_eq (N/m): the continuum-consistent stiffness (contact_solver.hpp, README
  // Eq. 11, 13–15), ER-7; at the positions of `stiffness_every` (the reference: every position), NaN
  // elsewhere.
  std::vector<double> stiffness;
  double smooth_approach = 0.0;      // δ_smooth (m)
  double smooth_stiffness = 0.0;     // k of the flat strip at W, the same discretisation (N/m)
  double smooth_contact_area = 0.0;  // contact area of the flat strip at W (m²)
  // CG iterations: fast path, of every solve (with the flat one); reference, of each position's last
  // Newton solve (solve_force returns the last solve); coarse starts excluded.
  int iterations = 0;
  double max_error = 0.0;  // largest stopping-rule ε (README Eq. 9) of the returned solves
  bool converged = false;  // every position met the stopping rule and the load tolerance
  // ER-8 only (empty otherwise): the checked positions' indices and r_j there (m).
  std::vector<std::size_t> check_index;
  std::vector<double> check_residual;
};

// ER-1, ER-2 on the moving window of `solver` (open boundary, same dx, dy as `strip`, not larger;
// with chunks, the other threads use solvers of the same grid and E*).
// `strip_heights`: strip.size() values (m, x-fastest). Throws std::invalid_argument on inconsistent
// input (as blocked_force_path), load ≤ 0, or a position whose δ_eq breaks BF-5 (message names it).
EquivalentRoughness equivalent_roughness(ContactSolver& solver, const Grid& strip,
                                         const std::vector<double>& strip_heights, double radius, BallShape shape,
                                         const std::vector<double>& positions, double load,
                                         const SolverOptions& options = {},
                                         const EquivalentRoughnessOptions& path_options = {});

// Plain reference: every position (and δ_smooth) an independent cold solve_force on the whole strip
// grid, the ball centred at (ξ_k, y_c). warm_start is ignored.
EquivalentRoughness equivalent_roughness_reference(const Grid& strip, const std::vector<double>& strip_heights,
                                                   double radius, BallShape shape, const std::vector<double>& positions,
                                                   double load, double e_star, const SolverOptions& options = {},
                                                   const EquivalentRoughnessOptions& path_options = {});

}  // namespace rollspec::contact
