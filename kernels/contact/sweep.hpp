#pragma once
// A warm-started sweep along increasing approach (seed 001 §3.3, kernels/README.md (contact)).
#include <vector>

#include "kernels/contact/contact_solver.hpp"

namespace rollspec::contact {

// Solves at each approach w_j (strictly increasing, else std::invalid_argument), each step
// warm-started from the previous pressure extrapolated along the frozen-set rate dp/dw
// (README Eq. 12). Every step is attempted; check each result's `converged` (all_converged).
// `pressure` (optional) holds the field of the last step on return.
std::vector<ContactResult> sweep(ContactSolver& solver, const std::vector<double>& gap,
                                 const std::vector<double>& approaches, const SolverOptions& options = {},
                                 std::vector<double>* pressure = nullptr);

bool all_converged(const std::vector<ContactResult>& results);

}  // namespace rollspec::contact
