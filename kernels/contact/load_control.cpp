// ContactSolver::solve_at_force: load control on the open half-space with the pressure cap
// (README Eq. 17, 17a, 17b; contact_solver.hpp): checks, then the shared Polonsky–Keer core
// (polonsky_keer.hpp) with the imposed-load policy (pk_force.cpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/pk_policies.hpp"
#include "kernels/contact/polonsky_keer.hpp"

namespace rollspec::contact {

using namespace detail;

ContactResult ContactSolver::solve_at_force(const std::vector<double>& s, double force, std::vector<double>& p,
                                            const SolverOptions& opt, double hint) {
  const Grid& grid = op_.grid();
  const std::size_t n = grid.size();
  const double area = grid.cell_area();
  const double hardness = opt.hardness;
  if (op_.boundary() != Boundary::Open)
    throw std::invalid_argument("solve_at_force: open boundary only (periodic: solve_load)");
  if (s.size() != n) throw std::invalid_argument("solve_at_force: gap size != grid size");
  if (!(hardness > 0.0)) throw std::invalid_argument("solve_at_force: hardness must be > 0 (may be +inf)");
  if (!(force >= 0.0) || !std::isfinite(force))
    throw std::invalid_argument("solve_at_force: force must be finite, >= 0");
  const double total = force / area;  // Σ p wanted
  if (std::isfinite(hardness) && !(total <= hardness * static_cast<double>(n)))
    throw std::invalid_argument("solve_at_force: force exceeds H times the grid area");
  if (p.size() != n) p.assign(n, 0.0);
  dp_.clear();
  ContactResult res;
  if (force == 0.0) {  // first contact, no pressure: D-7 holds exactly
    std::fill(p.begin(), p.end(), 0.0);
    res.approach = *std::min_element(s.begin(), s.end());
    res.converged = true;
    return res;
  }
  if (!box_) box_ = std::make_unique<BoxProduct>(op_);
  if (delta_.size() != n) delta_.assign(n, 0.0);

  ForcePolicy policy(PkArrays{u_, g_, t_, r_, x_, part_, set_}, ForcePolicy::Lists{listed_, free_, touched_, delta_},
                     op_, *box_, s, p, total, hint, opt, res);
  policy.start();
  res.iterations = polonsky_keer(policy, false, opt, res);
  res.approach = policy.approach();
  // Outputs (seed 001 Eq. 12; README Eq. 10): g is exact on L (a fresh product), p = 0 off L.
  summarise(p, g_, hardness, area, &listed_, res);
  return res;
}

}  // namespace rollspec::contact
