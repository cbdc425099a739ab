#pragma once
// Path table P(δ, ξ) of one rough strip (kernels/beam README B41–B43, issue 19 item 2): the force
// of the half-space contact solve at rigid approach δ (from the strip's mean plane, BF-1/BF-2) with
// the ball centred at ξ on the strip, on a grid of J approaches × N positions, and the exact
// first-contact approach δ_c(ξ_k) (B42). The solves run on the blocked force's moving window
// (blocked_force.hpp BF-5), position by position in fixed chunks of positions (one solver per OpenMP
// thread); at each position the approaches in increasing order, each started from the ones below
// it, extrapolated linearly (PT-1), the lowest from the previous position's lowest shifted with the
// ball (BF-6):
//
//     p^(j, k, start) = p^(j−1, k) + (δ_j − δ_{j−1}) / (δ_{j−1} − δ_{j−2}) (p^(j−1, k) − p^(j−2, k)),
//     p^(1, k, start) = p^(0, k),   p^(0, k, start) = p^(0, k−1)[ix − σ_k, iy]              (PT-1)
//
// (the solver clips the start to [0, H]). The first position of a chunk starts its lowest approach
// cold (coarse start, README Eq. 16). The cut depends on chunk_positions alone: the same bits for
// any thread count (the engine names the start and the cut among a cached table's inputs). The
// start changes only the iteration count (every solve runs to the stopping rule, README Eq. 9), and
// little: on the seed 002 rig (20 -> 20.5 mm, 370 solves) 33.2 CG iterations per solve from PT-1,
// 35.6 from the approach below alone, 38.2 along the path (BF-6), 33.1 cold (plus the coarse
// start's) — the same CPU time within the machine's noise. The contact set of the next approach
// differs from the start's where the new ring of contact forms; an exact start perturbed by 1e-6
// still takes 4–7 iterations to 1e-8.
// The interpolation (B44–B45) lives in kernels/beam/path_contact_table.hpp.
#include <cstddef>
#include <functional>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

// Where the approach rows stand (kernels/beam README B43, B43b).
enum class PathLadder {
  Plane,         // B43: one set of approaches δ_j from the mean plane, the same at every position
  FirstContact,  // B43b: δ_{j,k} = δ_c(ξ_k) + j s at each position, up to the first row carrying top_force · W
};

enum class PathTableStart {
  Approach,  // PT-1: from the approach below at the same position (the default)
  Position,  // every approach along the path on its own: the previous position's field shifted (BF-6)
  Cold,      // every solve cold (reference)
};

struct PathTableOptions {
  std::size_t approaches = 8;  // J (B43), 2 or more
  double reach = 3.0;          // δ_hi = max_k δ_c + reach · δ_H (B43)
  double centre_y = 0.0;       // lateral coordinate of the path (m)
  // B43a: rows are added above δ_J, with the same spacing, until every position carries at least
  // top_force · load at the last approach (0: none), at most max_approaches rows in all; a row the
  // solver window cannot hold (BF-5) ends the extension.
  double top_force = 5.0;
  std::size_t max_approaches = 24;
  PathLadder ladder = PathLadder::Plane;
  PathTableStart start = PathTableStart::Approach;
  std::size_t chunk_positions = 16;  // PT-1: fixed chunks of this many positions (0: one chunk)
  // Called after each chunk of positions is done (for every row of that pass), from the thread that
  // ran it, one call at a time: the rows of the pass, its positions done so far, and the chunk's
  // solves and CG iterations. Progress only: no effect on the table.
  std::function<void(std::size_t rows, std::size_t positions_done, int solves, int iterations)> on_chunk;
};

struct PathTable {
  std::vector<double> position;  // ξ_k (m, strip coordinates), N values
  // Plane: δ_j (m, from the plane h = 0), J or more values (B43a), increasing. FirstContact: the
  // offsets s_j = j s above δ_c(ξ_k) (B43b), as many as the longest position's ladder.
  std::vector<double> approach;
  PathLadder ladder = PathLadder::Plane;
  std::vector<std::size_t> rows;      // rows solved at each position (B43b; Plane: every row); NaN force above
  std::vector<double> first_contact;  // δ_c(ξ_k) (m), B42
  std::vector<double> force;          // P(δ_j, ξ_k) (N) at [j · N + k]
  int solves = 0, iterations = 0;     // contact solves and their CG iterations
  double max_error = 0.0;             // largest stopping-rule ε (contact README Eq. 9)
  bool converged = false;             // every solve converged
  double top_force = 0.0;             // min_k P(δ_last, ξ_k) / load (B43a)
};

// δ_c(ξ_k) = min_i s_i(ξ_k) over the strip (B42); `heights` empty: a smooth strip (δ_c = 0 up to
// the cell offset of the ball centre). Only columns within `half_columns` cells of ξ_k are visited
// (0: all): a cell farther out has s_i above every approach the table reaches (BF-5 checks it).
std::vector<double> first_contact_approach(const Grid& strip, const std::vector<double>& heights, double radius,
                                           BallShape shape, const std::vector<double>& positions, double centre_y,
                                           std::size_t half_columns = 0);

// The approaches of B43 for the ball's weight `load` (δ_H from E* and R); with options.ladder =
// FirstContact the offsets s_j = j · reach δ_H / J of B43b, j = 1 … max_approaches.
std::vector<double> path_table_approaches(const std::vector<double>& first_contact, double load, double e_star,
                                          double radius, const PathTableOptions& options = {});

// The table (B41–B43) on `window` (the solver grid, a window of `strip`: same cells), positions as
// blocked_force_path wants them (strictly increasing, whole cells apart). options.compute_stiffness
// is ignored (no stiffness is needed). Throws std::invalid_argument as blocked_force_path does
// (a position where the contact at δ_J could leave the window or the strip names it).
PathTable build_path_table(const Grid& window, double e_star, const Grid& strip, const std::vector<double>& heights,
                           double radius, BallShape shape, const std::vector<double>& positions, double load,
                           const SolverOptions& options = {}, const PathTableOptions& path_options = {});

// Plain reference: P(δ, ξ) by one cold contact solve on the whole strip grid (no window, no warm
// start), ball centred at (x, centre_y).
double path_force_direct(const Grid& strip, const std::vector<double>& heights, double e_star, double radius,
                         BallShape shape, double x, double centre_y, double approach,
                         const SolverOptions& options = {});

}  // namespace rollspec::contact
