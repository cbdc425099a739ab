#include "kernels/contact/contact_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/contact/cell_loops.hpp"
#include "kernels/contact/edge_correction.hpp"
#include "kernels/contact/pk_policies.hpp"
#include "kernels/contact/polonsky_keer.hpp"

namespace rollspec::contact {

using namespace detail;

ContactSolver::ContactSolver(const Grid& grid, double e_star, Boundary boundary, PlannerEffort effort)
    : op_(grid, e_star, boundary, effort) {
  const std::size_t n = grid.size();
  u_.assign(n, 0.0);
  g_.assign(n, 0.0);
  t_.assign(n, 0.0);
  r_.assign(n, 0.0);
  x_.assign(n, 0.0);
  gap_.assign(n, 0.0);
  set_.assign(n, kOut);
}

ContactResult ContactSolver::solve(const std::vector<double>& gap, double approach, std::vector<double>& pressure,
                                   const SolverOptions& options) {
  return run(gap, approach, false, pressure, options);
}

ContactResult ContactSolver::solve_load(const std::vector<double>& gap, double mean_pressure,
                                        std::vector<double>& pressure, const SolverOptions& options) {
  if (!std::isinf(options.hardness)) throw std::invalid_argument("solve_load: only hardness = +inf is supported");
  if (!(mean_pressure >= 0.0)) throw std::invalid_argument("solve_load: mean pressure must be >= 0");
  return run(gap, mean_pressure, true, pressure, options);
}

// The driver of the imposed approach (and of the periodic mean pressure): checks, the trivial
// no-contact case, the start (warm, coarse Eq. 16, or the policy's cold start), the shared
// Polonsky–Keer core (polonsky_keer.hpp), the outputs and the frozen-set stiffness (Eq. 11).
ContactResult ContactSolver::run(const std::vector<double>& s, double target, bool load, std::vector<double>& p,
                                 const SolverOptions& opt) {
  const Grid& grid = op_.grid();
  const std::size_t n = grid.size();
  const double hardness = opt.hardness;
  if (s.size() != n) throw std::invalid_argument("ContactSolver: gap size != grid size");
  if (!(hardness > 0.0)) throw std::invalid_argument("ContactSolver: hardness must be > 0 (may be +inf)");
  if (!std::isfinite(target)) throw std::invalid_argument("ContactSolver: approach / load must be finite");
  if (!load && op_.boundary() == Boundary::Periodic)
    throw std::invalid_argument("ContactSolver: periodic boundary needs load control (solve_load)");
  if (p.size() != n) p.assign(n, 0.0);
  dp_.clear();

  ContactResult res;
  const double w = target;
  double g_ref;  // the reference of ε (Eq. 9)
  if (load) {
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    g_ref = *hi - *lo;
    if (!(g_ref > 0.0)) g_ref = std::max(target * op_.self_coefficient(), 1e-300);
  } else {
    g_ref = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) g_ref = std::max(g_ref, w - s[i]);
  }
  const bool no_contact = load ? target == 0.0 : !(g_ref > 0.0);
  if (no_contact) {
    // No rigid interference (or zero load): p = 0 satisfies D-7 exactly.
    std::fill(p.begin(), p.end(), 0.0);
    res.approach = w;
    res.converged = true;
    res.stiffness = 0.0;
    res.frozen_stiffness = 0.0;
    res.stiffness_converged = true;
    return res;
  }

  // Displacement control: only the cells A = {s_i < w} can carry pressure (u = C p ≥ 0, so
  // g_i ≥ s_i − w > 0 elsewhere): the iteration works on A (README Eq. 6a); load control on all.
  active_.clear();
  if (!load)
    for (std::size_t i = 0; i < n; ++i)
      if (s[i] < w) active_.push_back(static_cast<std::uint32_t>(i));
  // Start: clip the warm start into [0, H]; cold start from the coarse grid's solution (Eq. 16),
  // else the policy's (one line search, or uniform pressure in load control).
  bool all_zero = true;
  for (std::size_t i = 0; i < n; ++i) {
    double& v = p[i];
    v = std::isnan(v) || (!load && !(s[i] < w)) ? 0.0 : clip(v, hardness);
    all_zero = all_zero && v == 0.0;
  }
  if (all_zero && !load && opt.coarse_start && coarse_start(s, w, p, opt, res)) all_zero = false;
  if (load && all_.size() != n) {
    all_.resize(n);
    for (std::size_t i = 0; i < n; ++i) all_[i] = static_cast<std::uint32_t>(i);
  }
  // C v on A: by direct sums while they are cheaper (Eq. 3b), else by DC-FFT (true: u on every cell).
  auto product = [this, load](const double* v, double* out) {
    return load ? (op_.apply(v, out), true) : apply_on(v, active_, out);
  };
  ApproachPolicy policy(PkArrays{u_, g_, t_, r_, x_, part_, set_}, product, s, p, load ? all_ : active_, target, load,
                        g_ref, op_.self_coefficient(), active_.size(), grid.nx, opt, res);
  const bool u_valid = policy.start(all_zero);
  res.iterations = polonsky_keer(policy, u_valid, opt, res);
  res.approach = policy.approach();
  if (!load) {
    // The outputs read the exact gap on the plastic cells (plastic volume) and on the open cells
    // within two cells of E (the sub-cell edge): u = C p on the box of the loaded cells {p > 0}
    // grown by two cells (Eq. 3d), zero outside it (not read there; the work arrays stay finite).
    if (!policy.u_full()) {
      loaded_.clear();
      for (const std::uint32_t i : active_)
        if (p[i] > 0.0) loaded_.push_back(i);
      apply_around(p.data(), loaded_, u_.data());
    }
    for (std::size_t i = 0; i < n; ++i) g_[i] = s[i] - w + u_[i];
  }
  summarise(p, g_, hardness, grid.cell_area(), nullptr, res);  // seed 001 Eq. 12; README Eq. 10
  if (opt.compute_stiffness && op_.boundary() == Boundary::Open) frozen_stiffness(p, opt, res);
  return res;
}

// README Eq. 3d: out = C v on the bounding box of `cells` grown by kOutputMargin cells (v is zero
// off `cells`), by the DC-FFT of the ladder box that holds it (Eq. 3c); zero outside that box. The
// whole grid's product when the grown box is the grid (then the same bits as op_.apply).
void ContactSolver::apply_around(const double* v, const std::vector<std::uint32_t>& cells, double* out) {
  const Grid& g = op_.grid();
  std::size_t x_lo = g.nx, x_hi = 0, y_lo = g.ny, y_hi = 0;
  for (const std::uint32_t i : cells) {
    x_lo = std::min<std::size_t>(x_lo, i % g.nx);
    x_hi = std::max<std::size_t>(x_hi, i % g.nx);
    y_lo = std::min<std::size_t>(y_lo, i / g.nx);
    y_hi = std::max<std::size_t>(y_hi, i / g.nx);
  }
  if (cells.empty() || op_.boundary() != Boundary::Open) {
    op_.apply(v, out);
    return;
  }
  x_lo = x_lo >= kOutputMargin ? x_lo - kOutputMargin : 0;
  y_lo = y_lo >= kOutputMargin ? y_lo - kOutputMargin : 0;
  x_hi = std::min(g.nx - 1, x_hi + kOutputMargin);
  y_hi = std::min(g.ny - 1, y_hi + kOutputMargin);
  around_.clear();
  for (std::size_t y = y_lo; y <= y_hi; ++y)
    for (std::size_t x = x_lo; x <= x_hi; ++x) around_.push_back(static_cast<std::uint32_t>(y * g.nx + x));
  if (!around_box_) around_box_ = std::make_unique<BoxProduct>(op_);
  around_box_->set_cells(around_);
  if (around_box_->box_nx() == g.nx && around_box_->box_ny() == g.ny) {
    op_.apply(v, out);
    return;
  }
  std::fill(out, out + g.size(), 0.0);
  around_box_->apply(v, out);
}

// C v on the cells `cells` (v = 0 elsewhere): direct sums over v's non-zero cells for those cells
// (README Eq. 3b) when they cost less than the DC-FFT product, which is used otherwise (and then
// gives u everywhere; returns true). The choice depends on the data only, never on threads.
bool ContactSolver::apply_on(const double* v, const std::vector<std::uint32_t>& cells, double* out) {
  if (op_.boundary() == Boundary::Open) {
    sources_.clear();
    for (std::uint32_t i : cells)
      if (v[i] != 0.0) sources_.push_back(i);
    // Eq. 3c: v is zero off `cells` and u is wanted on `cells` only: the product on the box that
    // holds them (the whole grid when no smaller box of the ladder does).
    if (!cell_box_) cell_box_ = std::make_unique<BoxProduct>(op_);
    // The box of a list is placed once: every CG iteration of a solve passes the same A (or E).
    if (cell_box_cells_ != cells) {
      cell_box_cells_ = cells;
      cell_box_->set_cells(cell_box_cells_);
    }
    const bool whole = cell_box_->box_nx() == op_.grid().nx && cell_box_->box_ny() == op_.grid().ny;
    if (static_cast<double>(sources_.size()) * static_cast<double>(cells.size()) < cell_box_->fft_cost()) {
      op_.apply_direct(v, sources_, cells, out);
      return false;
    }
    if (!whole) {
      cell_box_->apply(v, out);
      return false;
    }
  }
  op_.apply(v, out);
  return true;
}

// README Eq. 16: restrict the gap to the grid of 2dx × 2dy (2 × 2 means: the coarse cell centre is
// the mean of its four), solve there (itself coarse-started) to the coarse tolerance, and give each
// coarse pressure to its four fine cells. False (p untouched) when the grid is odd or too small.
bool ContactSolver::coarse_start(const std::vector<double>& s, double w, std::vector<double>& p,
                                 const SolverOptions& opt, ContactResult& res, bool reference) {
  constexpr std::size_t kMinCoarse = 32;
  const Grid& g = op_.grid();
  if (g.nx % 2 != 0 || g.ny % 2 != 0 || g.nx / 2 < kMinCoarse || g.ny / 2 < kMinCoarse) return false;
  const std::size_t cnx = g.nx / 2, cny = g.ny / 2;
  if (!coarse_) coarse_ = std::make_unique<ContactSolver>(Grid{cnx, cny, 2.0 * g.dx, 2.0 * g.dy}, op_.e_star());
  coarse_gap_.resize(cnx * cny);
  for (std::size_t y = 0; y < cny; ++y)
    for (std::size_t x = 0; x < cnx; ++x) {
      const std::size_t i = 2 * y * g.nx + 2 * x;
      coarse_gap_[y * cnx + x] = 0.25 * ((s[i] + s[i + 1]) + (s[i + g.nx] + s[i + g.nx + 1]));
    }
  SolverOptions o = opt;
  o.tolerance = std::max(opt.tolerance, opt.coarse_tolerance);
  o.compute_stiffness = false;
  coarse_pressure_.assign(cnx * cny, 0.0);
  const ContactResult r = reference ? coarse_->solve_reference(coarse_gap_, w, coarse_pressure_, o)
                                    : coarse_->solve(coarse_gap_, w, coarse_pressure_, o);
  res.coarse_iterations = r.iterations + r.coarse_iterations;
  bool any = false;
  for (std::size_t y = 0; y < g.ny; ++y)
    for (std::size_t x = 0; x < g.nx; ++x) {
      const std::size_t i = y * g.nx + x;
      const double v = s[i] < w ? coarse_pressure_[(y / 2) * cnx + x / 2] : 0.0;  // only A carries pressure (Eq. 6a)
      p[i] = v;
      any = any || v > 0.0;
    }
  return any;
}

// k = dP/dw with the contact set frozen (README Eq. 11): on the elastic contact cells E
// (0 < p < H) solve C_EE Δp = 1 by CG; plastic cells stay at H, open cells at 0; k = ΔA Σ Δp.
// Then the sub-cell edge correction δk (README Eq. 13–15): stiffness = k_frozen + δk.
void ContactSolver::frozen_stiffness(const std::vector<double>& p, const SolverOptions& opt, ContactResult& res,
                                     bool full_outputs) {
  const std::size_t n = p.size();
  const double hardness = opt.hardness;
  std::size_t m = 0;
  elastic_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    set_[i] = (p[i] > 0.0 && p[i] < hardness) ? kFree : kOut;
    m += set_[i];
    if (set_[i] == kFree) elastic_.push_back(static_cast<std::uint32_t>(i));
  }
  dp_.assign(n, 0.0);
  if (m == 0) {
    res.stiffness = 0.0;
    res.frozen_stiffness = 0.0;
    res.stiffness_converged = true;
    return;
  }
  gap_ = g_;  // the converged gap (g_ is the CG residual below)
  // x = Δp, g_ = residual, t_ = direction, r_ = C t. Start (Eq. 11a): the given rate on E, else 0.
  std::fill(x_.begin(), x_.end(), 0.0);
  const bool warm = rate_start_ != nullptr && rate_start_->size() == n;
  if (warm)
    for (const std::uint32_t i : elastic_) x_[i] = (*rate_start_)[i];
  // Preconditioned CG (README Eq. 7b on E; γ for the disc E itself, i.e. for |A| = 2|E|) with the
  // plain residual's stopping rule. g_ = residual, u_ = preconditioned residual, t_ = direction.
  const bool precondition = opt.precondition;
  const double gamma = precondition_gamma(2 * m);
  const std::size_t nx = op_.grid().nx;
  double rr = 0.0;
  if (warm) apply_on(x_.data(), elastic_, r_.data());  // C_EE x: only E is read
  for (std::size_t i = 0; i < n; ++i) {
    g_[i] = set_[i] == kFree ? 1.0 - (warm ? r_[i] : 0.0) : 0.0;
    rr += g_[i] * g_[i];
  }
  double rz = rr;
  const double rr0 = static_cast<double>(m);  // ‖1‖² on E: the stopping rule's reference
  if (precondition) {
    std::fill(u_.begin(), u_.end(), 0.0);
    rz = apply_preconditioner(elastic_, set_, g_, u_, gamma, nx, part_);
  }
  const std::vector<double>& z = precondition ? u_ : g_;
  t_ = z;
  const double stop = opt.stiffness_tolerance * opt.stiffness_tolerance * rr0;
  int it = 0;
  bool ok = rr <= stop;
  while (!ok && it < opt.stiffness_max_iterations) {
    apply_on(t_.data(), elastic_, r_.data());  // C_EE t: only E is read
    const double tr = block_reduce<1>(elastic_.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{elastic_.data(), lo, hi})
        if (set_[i] == kFree) acc[0] += t_[i] * r_[i];
    })[0];
    const double alpha = rz / tr;
    rr = block_reduce<1>(elastic_.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{elastic_.data(), lo, hi})
        if (set_[i] == kFree) {
          x_[i] += alpha * t_[i];
          g_[i] -= alpha * r_[i];
          acc[0] += g_[i] * g_[i];
        }
    })[0];
    ++it;
    ok = rr <= stop;
    const double rz_new = precondition ? apply_preconditioner(elastic_, set_, g_, u_, gamma, nx, part_) : rr;
    const double beta = rz_new / rz;
    rz = rz_new;
    block_reduce<0>(elastic_.size(), part_, [&](std::size_t lo, std::size_t hi, double*) {
      for (const std::size_t i : Slice{elastic_.data(), lo, hi}) t_[i] = set_[i] == kFree ? z[i] + beta * t_[i] : 0.0;
    });
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += x_[i];
  dp_ = x_;
  res.frozen_stiffness = op_.grid().cell_area() * sum;
  res.stiffness_converged = ok;
  res.stiffness_iterations = it;
  // Sub-cell contact edge (README Eq. 13–15): one more half-space product, u' = C dp, read on the
  // open cells within two cells of E: on E's box grown by two cells (Eq. 3d); the reference on all.
  if (full_outputs)
    op_.apply(dp_.data(), r_.data());
  else
    apply_around(dp_.data(), elastic_, r_.data());
  const EdgeCorrection edge =
      full_outputs ? edge_correction_reference(op_.grid(), op_.e_star(), res.approach, p, dp_, gap_, r_, hardness)
                   : edge_correction(op_.grid(), op_.e_star(), res.approach, p, dp_, gap_, r_, hardness);
  res.edge_correction = edge.delta_k;
  res.stiffness = res.frozen_stiffness + edge.delta_k;
}

}  // namespace rollspec::contact
