#pragma once
// Blocked force F0 and stiffness k0 of the linearised contact model (seed 002 §4.2, kernels/README.md D-11,
// issue 4 item 6): a smooth ball slid along a rough strip at a fixed rigid approach d0.
//
// Theory (equations BF-1 … BF-9; README Eq. n are the contact kernel's README equations).
//
// Strip and path. The strip is a height field h on the strip grid (x-fastest, centred on the
// origin as in Grid, longer in x than in y). The ball centre moves along y = y_c through the
// positions x_k (strictly increasing, every step x_k − x_{k−1} = m_k dx with m_k a positive
// integer). At position k the undeformed gap (README Eq. 5) is
//
//     s_i^(k) = z_ball(|r_i − (x_k, y_c)|) − h_i                                          (BF-1)
//
// and the blocked force is the force of the contact solve (D-7, README Eq. 6) at the FIXED rigid
// approach w = d (the ball's lowest point at z = −d: d is measured from the plane h = 0 — the
// strip's mean plane when the heights have zero mean, as D-11 wants —, not from first contact;
// on a rough strip d0 can be negative):
//
//     F0(x_k; d) = ΔA Σ_i p_i^(k)(d),    k(x_k; d) = dF0/dd  (frozen set, README Eq. 11)   (BF-2)
//
// Path means over the N positions: F̄(d) = (1/N) Σ_k F0(x_k; d), K̄(d) = (1/N) Σ_k k(x_k; d),
// k the frozen-set stiffness with the sub-cell contact edge (README Eq. 13–15); K̄_f the same mean
// of the frozen-set k_frozen (README Eq. 11), which between contact-set changes is the exact
// derivative of F̄, so
//
//     d0 solves F̄(d0) = W (the ball's weight);   k0 = K̄(d0)                               (BF-3)
//
// found by safeguarded Newton on d: d ← d + (W − F̄(d)) / K̄_f(d) inside the bracket
// [d_lo, d_hi] with F̄(d_lo) < W ≤ F̄(d_hi) (F̄ is non-decreasing in d), bisection when the Newton
// step leaves the bracket or K̄_f = 0, the bracket grown by doubling steps while one side is
// unknown. Start: the smooth Hertz approach for W (kernels/README.md (contact)),
//
//     d_start = (3 W / (4 E* R^{1/2}))^{2/3}                                               (BF-4)
//
// Stop when |F̄(d) − W| ≤ load_tolerance · W (every solve of that path converged to the solver's
// own tolerances). A path that starts cold (the first of each search: no earlier path's fields) only
// places the Newton step, its mean force being off the load by the start's error (on a rough strip
// the pre-search's sampling error, ~1e-2): its solves and stiffness solves stop at
// max(tolerance, cold_tolerance), and it is never accepted as the result (measured on the seed 002
// rig: its CG + stiffness iterations per position 30.9 + 24.2 → 19.4 + 8.4, the next path's
// unchanged).                                                                              (BF-4'')
// A long path
// (N ≥ 4 M positions, M = presearch_positions) is first searched on every S-th position,
// S = ⌊N/M⌋, to 1e-6 relative; its root starts the full search (measured: 3 full paths instead
// of 5 on a seed-like rough strip, 2 instead of 3 on the long-wave test).                   (BF-4')
//
// Moving window. The contact solver's grid is a window of the strip: same dx, dy, nx_w ≤ nx_s,
// ny_w ≤ ny_s. Its rows are fixed, centred on y_c (clamped to the strip); at position k it covers
// strip columns j_k … j_k + nx_w − 1 with
// j_k = clamp(j_0 + Σ_{l≤k} m_l, 0, nx_s − nx_w), j_0 the column start that centres the window on
// x_0 (so the ball sits at the same sub-cell offset at every position). On the open half-space
// (README Eq. 3) the window solve equals the solve on the whole strip exactly as long as every
// cell that can touch lies inside the window; a cell can touch only if it has rigid interference,
// so the kernel requires, at every position,
//
//     s_i^(k) ≥ d  for every strip cell i outside the window and for every cell on the strip's
//     edge (first/last row and column: beyond them the surface is unknown)                (BF-5)
//
// i.e. d ≤ d_max(k) = min of s_i^(k) over those cells, computed once per path set-up (columns outside
// the window are screened with the bound s_i ≥ z_ball(|x_i − x_k|) − max_iy h(x_i, ·)). A path at
// d > d_max(k) is refused with std::invalid_argument naming the position k; the load search keeps
// d ≤ min_k d_max(k) and is refused, naming the limiting position, if W needs more.
// A solver grid equal to the strip grid is the special case j_k = 0 (the ball moves in the grid).
// Cost: the half-space product runs on the smallest 2^a 3^b 5^c 7^d ≥ 2n − 1 points per axis
// (README Eq. 3; before kernel version 4, 2n: a 101² window cost 6× a 100² one).
//
// Warm start. The ball moves by σ_k = m_k − (j_k − j_{k−1}) cells relative to the window; the
// start of solve k is the previous field shifted with the ball (cells shifted in are 0),
//
//     p^(k, start)[ix, iy] = p^(k−1)[ix − σ_k, iy]                                          (BF-6)
//
// (`PathWarmStart::Ball`, exact for a smooth strip), or kept fixed to the strip,
// shift −(j_k − j_{k−1}) (`PathWarmStart::Strip`: the contact spots of a rough strip stay on
// their asperities), or cold (`PathWarmStart::Cold`). In blocked_force_at_load every path after
// the first starts each position from the same position on the previous path (approach d'),
// extrapolated along its frozen-set rate (README Eq. 12),
//
//     p^(k, start)(d) = p^(k)(d') + (d − d') dp^(k)/dd                                    (BF-6')
//
// (Cold: no reuse). The start only changes the iteration count: every solve is run to the
// solver's stopping rule (README Eq. 9). Measured (tolerance 1e-10, H = 5 GPa, 40 mm ball, Gaussian
// strip σ = 0.3 µm, correlation length 10 µm, 4 µm cells, 100² window, steps of 8 µm): CG
// iterations per solve along one path 23.9 (Ball), 20.6 (Strip), 23.4 (Cold) — on a rough strip
// the shifted start saves little; BF-6' brings the load search to 9.2 per solve, and the
// frozen-set stiffness (cold-started inside ContactSolver) adds 21.3 per solve.
//
// Chunks. With chunk_positions = m > 0 the path is cut into fixed chunks of m positions; each chunk
// starts cold (or from BF-6') and warm-starts along itself by BF-6, the chunks run in parallel, one
// solver per thread; the frozen-set CG starts from the previous path's rate (README Eq. 11a). The cut
// depends on m alone, so the path has the same bits for any thread count. The pre-search's subset
// (BF-4'), whose positions lie farther apart than a window, is cut in four chunks.         (BF-6c)
//
// One path at the answer's accuracy (answer_tolerance > 0; 0, the default, is the exhaustive search
// above, the reference). After the pre-search (BF-4'), ONE path at its root d: solves and stiffness
// solves to max(tolerance, answer_tolerance), cold-started per chunk (BF-6c, BF-6) — more paths of the
// search (BF-3, BF-6') at that tolerance only while |F̄ − W| > answer_load_tolerance · W (1e-2: k0 must follow
// the step to ~0.2 %, BF-8') —, then moved onto the load to first order along the edge-corrected stiffness
// (README Eq. 13–15),
//
//     δd = (W − F̄(d)) / K̄(d),  d0 = d + δd,  F0(x_k; d0) = F0(x_k; d) + δd k(x_k; d)       (BF-8)
//
// so the mean meets W exactly; k moves with it, k(x_k; d0) = k(x_k; d) (1 + δd K̄'/K̄), K̄'/K̄ the secant
// of K̄ over the search's exact paths (its own if it ran two, else the pre-search's)      (BF-8')
// Its own error bound per position: the two slopes' disagreement over
// the step, |δd| |k − k_frozen| (the contact edge's growth, which the first order cannot place
// closer), plus the solve's ε (README Eq. 9) times |F0|. Measured on the seed 002 rig (1024
// positions, answer_tolerance 1e-3, whole `run`): F0's third-octave band levels within 0.003 dB of the
// exhaustive search, k0 within 2e-4, the study's bands within 0.03 dB, at 0.6-0.7 of its CPU (two paths:
// the pre-search left the load 1.4e-2 off; stopping at that one path, 0.5 of the CPU, left k0 0.4 % off
// and the bands 0.12 dB, through the contact resonance). Every m-th position instead aliases F0 (m = 2:
// 0.11 dB, bench/contact/measurement_log.md).
//
// One loose path, checked (check_stride > 0 with answer_tolerance > 0; issue 51). BF-8's path, its search
// stopped within answer_load_tolerance (5e-2 in the engine: one path after the pre-search), put on the load
// by BF-8's first-order step, and then every check_stride-th position solved again to the full tolerance at
// d1 = d + δd, each from its own loose field moved along its rate (BF-6'). The checks are a systematic
// sample of the path: k0 comes from them by a control variate on the loose path's k, with its standard
// error (BF-9a); the residuals r_j of the tabulated F0 there measure its error (BF-9b); their mean puts
// the table on the load by a second step (BF-9d). While k0's standard error is above check_k0_tolerance
// (1e-3 in the engine) the stride halves, down to the finest whose loose fields fit in max_stored_bytes:
// the refinement goes where the estimate says the answer needs it. A strip too long for every
// check_stride-th field in max_stored_bytes starts at the smallest power-of-two multiple of the stride that
// fits (the seed 002 rig's whole 0.35 m traverse: every 32nd of 16,385 positions). kernels/contact/answer_error.hpp
// carries the residuals to the band levels (BF-9c). Measured on the seed 002 rig and two other textures
// (bench/contact/bench_answer_tables.py, record answer-tables.json on the benchmarks page, 2026-11-30):
// the table 1.9-2.0 times faster than the exhaustive search (1.4 where the checks refine), F0's band
// levels within 0.011 dB of it, k0 within 3e-4.                                        (BF-9a, b, d)
//
// Use in the dynamics (D-11): F_c = F0(t) + k0 (w1(ξ) − w2 + d0) + c0 (ẇ1 − ẇ2) with
// F0(t) = F0(x = v t); the PSD of F0 along the path in cycles/m (sample rate 1/Δx) is mapped to
// time by D-2.                                                                              (BF-7)
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

enum class PathWarmStart {
  Ball,   // previous field shifted with the ball (BF-6), the default
  Strip,  // previous field kept on the strip (contact spots stay on their asperities)
  Cold,   // every position from a cold start (reference)
};

struct BlockedForcePath;

struct BlockedForceOptions {
  double centre_y = 0.0;  // lateral coordinate y_c of the path in the strip grid (m)
  PathWarmStart warm_start = PathWarmStart::Ball;
  double load_tolerance = 1e-10;         // blocked_force_at_load: stop when |F̄ − W| ≤ load_tolerance · W
  int max_paths = 60;                    // blocked_force_at_load: path evaluations allowed (BF-3), per search
  std::size_t presearch_positions = 32;  // BF-4': M positions of the pre-search (0: none)
  double cold_tolerance = 1e-4;          // BF-4'': a cold-started path's solves stop here (0: at the solver's)
  // BF-6c: fixed chunks of this many positions (0: one chunk, the whole path in order). Each chunk
  // starts cold (or from the previous path's fields, BF-6') and warm-starts along itself (BF-6);
  // the chunks run in parallel (OpenMP, one solver per thread). The cut depends on this number
  // alone: the same bits for any thread count.
  std::size_t chunk_positions = 0;
  // BF-8: > 0, one path with its solves to this tolerance, moved onto the load to first order;
  // 0 (default): the exhaustive search (BF-3), the reference path.
  double answer_tolerance = 0.0;
  // BF-8: its paths (solved to answer_tolerance) stop when |F̄ − W| ≤ this · W; the first-order step
  // then puts the mean on W.
  double answer_load_tolerance = 1e-2;
  // BF-9 (with answer_tolerance > 0): every check_stride-th position (a power of two) solved again to the
  // full tolerance after the first-order step, finer levels while k0's error is above check_k0_tolerance;
  // k0 by the control variate BF-9a with its standard error, F0's residuals there kept (BF-9b). 0: BF-8
  // alone (k moved by the secant BF-8'); also when the path has fewer than 2 checks. On a strip whose every
  // check_stride-th loose field does not fit in max_stored_bytes, every 2^j check_stride-th that does.
  std::size_t check_stride = 0;
  // BF-9: the check levels halve the stride (down to the finest whose loose fields fit in max_stored_bytes)
  // while k0's standard error is above this times k0.
  double check_k0_tolerance = 1e-3;
  // blocked_force_at_load keeps each position's field and rate dp/dd (16 bytes per window cell and
  // position) to start the next path from (BF-6') while they fit in this many bytes;
  // beyond it only the first position's.
  std::size_t max_stored_bytes = std::size_t{256} << 20;
  // blocked_force_at_load calls this after every path it evaluates (pre-search paths on the subset
  // too), with that path (positions, its solves' CG and stiffness iterations) and its relative load
  // error |F̄ − W| / W: a search can take many seconds, and its caller shows progress. No effect
  // on the result.
  std::function<void(const BlockedForcePath& path, double load_error)> on_path;
  // Called after every chunk of positions of every path (BF-6c; the whole path when unchunked), one
  // call at a time from the thread that ran it: that chunk's positions and the path's length.
  // Progress only: no effect on the result.
  std::function<void(std::size_t positions, std::size_t path_positions)> on_chunk;
  // BF-9: called after each level of checks, with that level's path (its positions, iterations), its
  // stride and k0's relative standard error over every position checked so far. Progress only.
  std::function<void(const BlockedForcePath& level, std::size_t stride, double k0_error)> on_check;
};

struct BlockedForcePath {
  std::vector<double> position;  // x_k (m, strip coordinates)
  std::vector<double> force;     // F0(x_k; d0) (N), BF-2
  std::vector<double>
      stiffness;  // k(x_k; d0) (N/m), frozen set + sub-cell edge (README Eq. 13–15); NaN if not computed
  std::vector<double> frozen_stiffness;  // k_frozen(x_k; d0) (N/m), README Eq. 11; NaN if not computed
  // BF-8 only (empty otherwise): the bound |δd| |k − k_frozen| + ε |F0| on each F0 (N).
  std::vector<double> force_error;
  // BF-9 only (empty / NaN otherwise): the checked positions' indices, F0(x_j; d0) of the full-tolerance
  // solve minus the tabulated F0 there (N), and k0's standard error (N/m, BF-9a).
  std::vector<std::size_t> check_index;
  std::vector<double> check_residual;
  double k0_error = std::numeric_limits<double>::quiet_NaN();
  double k0_step = 0.0;          // BF-8': the relative change of k0 (and of every k) moved with the step
  double load_step = 0.0;        // BF-8: δd (m), the first-order step onto the load (0 for the exhaustive search)
  double approach = 0.0;         // d0 (m), from the plane h = 0 (BF-2)
  double k0 = 0.0;               // K̄(d0) (N/m), BF-3, mean of `stiffness`; NaN if stiffness not computed
  double k0_frozen = 0.0;        // the same mean of the frozen-set k (README Eq. 11): exact dF̄/dd
  double mean_force = 0.0;       // F̄(d0) (N)
  double max_error = 0.0;        // largest stopping-rule ε (README Eq. 9) of the returned path
  int paths = 0;                 // full-path evaluations (1 for blocked_force_path)
  int presearch_paths = 0;       // evaluations of the pre-search subset (BF-4')
  int solves = 0;                // contact solves over all paths (pre-search included)
  int iterations = 0;            // CG iterations of those solves
  int stiffness_iterations = 0;  // CG iterations of their frozen-set stiffness solves
  // Every solve (and stiffness solve, if computed) of the returned path converged; for
  // blocked_force_at_load also |F̄ − W| ≤ load_tolerance · W. Never true for an unfinished result.
  bool converged = false;
};

// F0 and k along the path at the fixed approach d = `approach` (BF-1, BF-2), warm-started (BF-6).
// `solver` must be an open-boundary solver on a window of `strip` (same dx, dy; nx, ny ≤ the strip's).
// `strip_heights`: strip.size() values (m), or empty for a smooth strip. `options` are the
// contact solver's (hardness, tolerance, …; stiffness only if options.compute_stiffness).
// Throws std::invalid_argument on inconsistent sizes/grids, bad positions (not strictly
// increasing, a step that is not a whole number of cells dx), or a position where the contact
// can leave the window or the strip (BF-5; the message names the position).
BlockedForcePath blocked_force_path(ContactSolver& solver, const Grid& strip, const std::vector<double>& strip_heights,
                                    double radius, BallShape shape, const std::vector<double>& positions,
                                    double approach, const SolverOptions& options = {},
                                    const BlockedForceOptions& path_options = {});

// The path at the approach d0 whose mean force equals `load` W > 0 (BF-3, BF-4); stiffness is
// always computed. `solves`/`iterations` count every path evaluated. An unconverged solve stops
// the search and is returned with converged = false. Throws std::invalid_argument as
// blocked_force_path, and when W needs an approach beyond the confinement limit (BF-5).
BlockedForcePath blocked_force_at_load(ContactSolver& solver, const Grid& strip,
                                       const std::vector<double>& strip_heights, double radius, BallShape shape,
                                       const std::vector<double>& positions, double load,
                                       const SolverOptions& options = {}, const BlockedForceOptions& path_options = {});

}  // namespace rollspec::contact
