#pragma once
// The one Polonsky–Keer iteration of the contact solver (README Eq. 6–10, 17; Polonsky & Keer
// 1999): the control flow both ContactSolver::solve (imposed approach, or the periodic mean
// pressure) and ContactSolver::solve_at_force (imposed total load) run, with what differs between
// the two constraints behind a policy (pk_policies.hpp). Internal to the kernel.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/contact/contact_solver.hpp"

namespace rollspec::contact::detail {

// A constraint policy: the state of one solve (p, u = C p, g, the CG set S and direction t) and
// the steps of Eq. 6–10 that depend on what is imposed. The core calls them in a fixed order.
class PkPolicy {
 public:
  virtual ~PkPolicy() = default;
  // u = C p by a half-space product: the exact gap replaces the carried one (Eq. 7a).
  virtual void refresh() = 0;
  // w (when it is the multiplier), g = s − w + u, the CG set S, G = Σ_S g² and ε of Eq. 9
  // (written to the result's `error`).
  virtual void evaluate() = 0;
  // After evaluate: anything that must hold before the iteration decides (load control: every
  // cell with s < w listed, Eq. 6a; γ of Eq. 7b). True if it made u fresh by a product.
  virtual bool prepare() = 0;
  // The search direction t on S and the step's numerator Σ_S g t and denominator Σ_S (C t) t
  // (Eq. 7, 7b, 17a); leaves den = 0 if S has nothing to move.
  virtual void direction(double& num, double& den) = 0;
  // Fallback when den ≤ 0: the bound cells whose gap says they must leave the bound join S
  // (Eq. 8), the conjugation is dropped and the direction formed again.
  virtual void release(double& num, double& den) = 0;
  // The step p ← Π_[0,H](p − τ t) on S with the releases of Eq. 8 (and the load balance of
  // Eq. 17b); `released` from the fallback. True if u = C p was carried exactly (Eq. 7a, 17b).
  virtual bool step(double tau, bool released) = 0;
};

// Iterates to res.error < tolerance or max_iterations (SolverOptions), from the policy's start;
// `u_valid`: u = C p already holds. Sets res.converged and returns the iteration count. Every
// exit decides on a fresh product, so u and g are exact on the policy's cells on return.
int polonsky_keer(PkPolicy& policy, bool u_valid, const SolverOptions& options, ContactResult& res);

// The outputs of a solve (seed 001 Eq. 12; README Eq. 10) from p and the exact gap g: force,
// contact cells and area, plastic cells and volume, max pressure. Summed over `cells` in order,
// or over every cell when `cells` is null.
void summarise(const std::vector<double>& p, const std::vector<double>& g, double hardness, double cell_area,
               const std::vector<std::uint32_t>* cells, ContactResult& res);

}  // namespace rollspec::contact::detail
