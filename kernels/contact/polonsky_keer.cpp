#include "kernels/contact/polonsky_keer.hpp"

#include <algorithm>

namespace rollspec::contact::detail {

int polonsky_keer(PkPolicy& pk, bool u_valid, const SolverOptions& opt, ContactResult& res) {
  int it = 0;
  for (;; ++it) {
    bool fresh = false;  // u from a product this iteration (not carried by the steps, Eq. 7a)
    if (!u_valid) {
      pk.refresh();
      fresh = true;
    }
    pk.evaluate();
    if (pk.prepare()) fresh = true;
    if ((res.error < opt.tolerance || it >= opt.max_iterations) && !fresh) {
      // Decide on, and report, the exact gap: one product replaces the carried u.
      pk.refresh();
      fresh = true;
      pk.evaluate();
    }
    if (res.error < opt.tolerance) {
      res.converged = true;
      break;
    }
    if (it >= opt.max_iterations) break;
    double num = 0.0, den = 0.0;
    pk.direction(num, den);
    bool released = false;
    if (!(den > 0.0)) {
      released = true;
      pk.release(num, den);
    }
    if (!(den > 0.0)) {
      ++it;  // nothing left to move: stop; reported unconverged since ε ≥ tolerance
      if (!fresh) {
        pk.refresh();
        pk.evaluate();
      }
      break;
    }
    u_valid = pk.step(num / den, released);
  }
  return it;
}

void summarise(const std::vector<double>& p, const std::vector<double>& g, double hardness, double cell_area,
               const std::vector<std::uint32_t>* cells, ContactResult& res) {
  double force = 0.0, vp = 0.0, pmax = 0.0;
  auto add = [&](std::size_t i) {
    force += p[i];
    pmax = std::max(pmax, p[i]);
    if (p[i] > 0.0) ++res.contact_cells;
    if (p[i] == hardness) {
      ++res.plastic_cells;
      vp += std::max(0.0, -g[i]);
    }
  };
  if (cells != nullptr) {
    for (const std::uint32_t i : *cells) add(i);
  } else {
    for (std::size_t i = 0; i < p.size(); ++i) add(i);
  }
  res.force = cell_area * force;
  res.contact_area = cell_area * static_cast<double>(res.contact_cells);
  res.plastic_volume = cell_area * vp;
  res.max_pressure = pmax;
}

}  // namespace rollspec::contact::detail
