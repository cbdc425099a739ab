#pragma once
// Elastic–perfectly-plastic rough contact by constrained conjugate gradients
// (Polonsky & Keer 1999, pressure cap after Almqvist et al. 2007; kernels/README.md D-6, D-7,
// README Eq. 6–15).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "kernels/contact/box_product.hpp"
#include "kernels/contact/grid.hpp"
#include "kernels/contact/half_space_operator.hpp"

namespace rollspec::contact {

struct SolverOptions {
  // Pressure cap H (Pa), "hardness"; +inf means purely elastic. Must be > 0.
  double hardness = std::numeric_limits<double>::infinity();
  // Stopping rule (README Eq. 9): stop when ε = max_i e_i / g_ref < tolerance, with the natural
  // KKT residual of the box-constrained problem (D-7), in length units,
  //   e_i = c |p_i − Π_[0,H](p_i − g_i/c)|,   c = C_ii (self coefficient),
  // i.e. e_i = |g_i| on cells with 0 < p_i < H (gap must close), max(0, −g_i) on p_i = 0 (no
  // interpenetration), max(0, g_i) on p_i = H (a saturated cell must still be pressed), each capped
  // by c·p_i resp. c·(H − p_i). g_ref = max_i (w − s_i), the largest rigid interference
  // (displacement control); max_i s_i − min_i s_i in load control.
  double tolerance = 1e-10;
  // A solve that reaches this many iterations without meeting the stopping rule returns
  // converged = false: its fields describe the last iterate, not a solution.
  int max_iterations = 10000;
  // Frozen-set stiffness k = dP/dw (README Eq. 11), by CG on the elastic contact cells, stopped at
  // ‖1 − C_EE Δp‖₂ / ‖1‖₂ < stiffness_tolerance. Open boundary only (NaN for periodic).
  bool compute_stiffness = true;
  // Cold start (displacement control, no warm start given) from the solution on the grid of
  // twice the cell size, itself started the same way (README Eq. 16): the 2 × 2 mean of the gap,
  // solved to coarse_tolerance, each coarse cell's pressure given to its four cells. Only for even
  // nx and ny whose halves are ≥ 32 (else the line-search start of Eq. 7).
  bool coarse_start = true;
  double coarse_tolerance = 1e-3;
  // Precondition the CG on S with I + γ L_S (README Eq. 7b; L_S the 5-point Laplacian on S with
  // zero outside it), γ = 0.1 √(|A|/2π) from the interference set A (Eq. 6a): the contact radius
  // in cells for a ball. Displacement control only; also the frozen-set stiffness CG (on E).
  bool precondition = true;
  double stiffness_tolerance = 1e-12;
  int stiffness_max_iterations = 10000;
};

struct ContactResult {
  double approach = 0.0;      // rigid approach w (m): given, or found in load control
  bool converged = false;     // stopping rule met (never true for an unfinished solve)
  int iterations = 0;         // CG iterations (at most two half-space products each)
  int coarse_iterations = 0;  // CG iterations of the coarse start on all coarser grids (Eq. 16)
  double error = 0.0;         // ε of README Eq. 9 at the returned field
  double force = 0.0;         // P = ΔA Σ p_i (N), seed 001 Eq. 12
  double contact_area = 0.0;  // ΔA · #{p_i > 0} (m²)
  std::size_t contact_cells = 0;
  std::size_t plastic_cells = 0;  // #{p_i = H}
  double plastic_volume = 0.0;    // V_p = ΔA Σ_{p_i = H} max(0, −g_i) (m³), README Eq. 10
  double max_pressure = 0.0;      // max_i p_i (Pa)
  // k (N/m): the frozen-set stiffness with the sub-cell contact edge, k_frozen + δk (README
  // Eq. 11, 13–15): the continuum-consistent contact stiffness (tables, blocked force k0).
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  // k_frozen = dP/dw of the discrete problem on the frozen set (README Eq. 11): the exact derivative
  // of `force` between contact-set changes (Newton steps on w use it).
  double frozen_stiffness = std::numeric_limits<double>::quiet_NaN();
  double edge_correction = 0.0;  // δk = stiffness − frozen_stiffness (README Eq. 15)
  bool stiffness_converged = false;
  int stiffness_iterations = 0;
};

class ContactSolver {
 public:
  ContactSolver(const Grid& grid, double e_star, Boundary boundary = Boundary::Open,
                PlannerEffort effort = PlannerEffort::Estimate);

  // Displacement control: rigid approach w given (m). `gap` is the undeformed gap s (ball_gap).
  // `pressure` (Pa, x-fastest) is the warm start on entry (empty or all zero: cold start) and the
  // solution on return. Throws std::invalid_argument on size mismatch or hardness ≤ 0.
  ContactResult solve(const std::vector<double>& gap, double approach, std::vector<double>& pressure,
                      const SolverOptions& options = {});

  // Load control (Polonsky & Keer's original form): mean pressure over the grid given (Pa), the
  // approach w is the Lagrange multiplier. Needed for Boundary::Periodic. Requires hardness = +inf.
  ContactResult solve_load(const std::vector<double>& gap, double mean_pressure, std::vector<double>& pressure,
                           const SolverOptions& options = {});

  // Load control on the open half-space (Polonsky & Keer's original form with the pressure cap;
  // README Eq. 17, 17a, 17b): the total force F = ΔA Σ p (N) is given and the approach w is the
  // Lagrange multiplier of that constraint, w = the mean of s + u over the cells with 0 < p < H.
  // The CG directions on the free set have zero sum (Eq. 17a), so the steps keep the force; a step
  // that clips or releases cells is followed by the rescaling of the free cells to F (Eq. 17b).
  // Stops by the rule of README Eq. 9 with g_ref = max_i (w − s_i) at the current w: the rule of a
  // displacement-controlled solve at the returned approach (which would return this field at once).
  // `pressure`: the warm start (empty or all zero: cold start) and the solution. `approach_hint`
  // (m, optional), an estimate of w (e.g. the previous position's): the iteration then visits only
  // the cells with s_i < w_L = hint + 0.2 (hint − min s) or p_i > 0 (Eq. 6a: only s_i < w can carry
  // pressure; w_L is raised and the cells listed again whenever w passes it) with products on the
  // box that holds them (Eq. 3c); a cold start with a hint starts from max(0, hint − s) scaled to F,
  // without one from uniform pressure on every cell. No stiffness is computed (NaN; the options'
  // compute_stiffness and coarse_start are not used). Throws std::invalid_argument for the periodic
  // boundary, a size mismatch, F < 0 or not finite, hardness ≤ 0, or F > H ΔA nx ny.
  ContactResult solve_at_force(const std::vector<double>& gap, double force, std::vector<double>& pressure,
                               const SolverOptions& options = {},
                               double approach_hint = std::numeric_limits<double>::quiet_NaN());

  // Plain references (contact_solver_reference.cpp, load_control_reference.cpp): the two
  // Polonsky–Keer loops as first written, kept beside the shared core (polonsky_keer.hpp) so the
  // doctests can check that the core gives the same bits. Same contracts as solve, solve_load and
  // solve_at_force.
  ContactResult solve_reference(const std::vector<double>& gap, double approach, std::vector<double>& pressure,
                                const SolverOptions& options = {});
  ContactResult solve_load_reference(const std::vector<double>& gap, double mean_pressure,
                                     std::vector<double>& pressure, const SolverOptions& options = {});
  ContactResult solve_at_force_reference(const std::vector<double>& gap, double force, std::vector<double>& pressure,
                                         const SolverOptions& options = {},
                                         double approach_hint = std::numeric_limits<double>::quiet_NaN());

  // dp/dw on the frozen contact set from the last solve with stiffness (empty if none): the sweep
  // uses it to extrapolate the warm start to the next approach.
  const std::vector<double>& pressure_rate() const { return dp_; }
  // Start of the next frozen-set stiffness CG (README Eq. 11a): an estimate of dp/dw (e.g. the same
  // position's rate at a nearby approach, blocked_force BF-6'), used on the elastic set of that
  // solve only; null or a wrong size: the cold start Δp = 0. Kept by pointer until changed.
  void set_rate_start(const std::vector<double>* rate) { rate_start_ = rate; }

  HalfSpaceOperator& half_space() { return op_; }
  const Grid& grid() const { return op_.grid(); }

 private:
  ContactResult run(const std::vector<double>& gap, double target, bool load, std::vector<double>& pressure,
                    const SolverOptions& options);
  ContactResult run_reference(const std::vector<double>& gap, double target, bool load, std::vector<double>& pressure,
                              const SolverOptions& options);
  // `full_outputs`: u' = C dp on the whole grid (the reference) instead of around E (Eq. 3d).
  void frozen_stiffness(const std::vector<double>& pressure, const SolverOptions& options, ContactResult& result,
                        bool full_outputs = false);
  // The outputs' products (gap, u' = C dp): on the box of the cells grown by this many cells (Eq. 3d).
  static constexpr std::size_t kOutputMargin = 2;
  void apply_around(const double* v, const std::vector<std::uint32_t>& cells, double* out);

  HalfSpaceOperator op_;
  std::vector<double> u_, g_, t_, r_, x_, gap_;  // work arrays, one set per solver (thread-private use)
  std::vector<unsigned char> set_;
  std::vector<double> dp_;
  const std::vector<double>* rate_start_ = nullptr;
  std::vector<double> part_;  // per-block partial sums of the cell loops
  bool apply_on(const double* v, const std::vector<std::uint32_t>& cells, double* out);
  std::vector<std::uint32_t> active_, elastic_, sources_, all_;  // A (Eq. 6a), E, v ≠ 0, every cell
  // Coarse start (Eq. 16): the solver on the grid of twice the cell size, made when first needed.
  bool coarse_start(const std::vector<double>& gap, double approach, std::vector<double>& pressure,
                    const SolverOptions& options, ContactResult& result, bool reference = false);
  std::unique_ptr<ContactSolver> coarse_;
  std::vector<double> coarse_gap_, coarse_pressure_;
  // Load control (solve_at_force): products on the box of the listed cells; the listed cells L; a
  // step's departures from −τ t (clipped, released, rescaled cells) and where they are.
  std::unique_ptr<BoxProduct> box_;
  std::unique_ptr<BoxProduct> cell_box_;       // displacement control: products on the box of A or E (Eq. 3c)
  std::vector<std::uint32_t> cell_box_cells_;  // the cells cell_box_ was placed for
  std::vector<std::uint32_t> listed_, free_, touched_;
  std::vector<double> delta_;
  std::unique_ptr<BoxProduct> around_box_;  // the outputs' products (Eq. 3d) and their cells
  std::vector<std::uint32_t> around_, loaded_;
};

}  // namespace rollspec::contact
