#include "kernels/contact/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/contact/edge_correction.hpp"

namespace rollspec::contact {

namespace {
constexpr unsigned char kOut = 0;   // not in the CG set this iteration
constexpr unsigned char kFree = 1;  // 0 < p < H: CG set (README Eq. 7)

double clip(double v, double hardness) { return std::min(std::max(v, 0.0), hardness); }

// Natural KKT residual of D-7 in length units (README Eq. 9), maximum over cells.
double kkt_residual(const std::vector<double>& p, const std::vector<double>& g, double hardness, double c) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e = std::max(e, std::fabs(p[i] - clip(p[i] - g[i] / c, hardness)));
  return c * e;
}
}  // namespace

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

ContactResult ContactSolver::run(const std::vector<double>& s, double target, bool load, std::vector<double>& p,
                                 const SolverOptions& opt) {
  const Grid& grid = op_.grid();
  const std::size_t n = grid.size();
  const double area = grid.cell_area();
  const double hardness = opt.hardness;
  const double c = op_.self_coefficient();
  if (s.size() != n) throw std::invalid_argument("ContactSolver: gap size != grid size");
  if (!(hardness > 0.0)) throw std::invalid_argument("ContactSolver: hardness must be > 0 (may be +inf)");
  if (!std::isfinite(target)) throw std::invalid_argument("ContactSolver: approach / load must be finite");
  if (!load && op_.boundary() == Boundary::Periodic)
    throw std::invalid_argument("ContactSolver: periodic boundary needs load control (solve_load)");
  if (p.size() != n) p.assign(n, 0.0);
  dp_.clear();

  ContactResult res;
  double w = target;
  double g_ref;
  if (load) {
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    g_ref = *hi - *lo;
    if (!(g_ref > 0.0)) g_ref = std::max(target * c, 1e-300);
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

  // Start: clip the warm start into [0, H]; cold start from the best multiple of the rigid
  // interference (one line search), or uniform pressure in load control.
  bool all_zero = true;
  for (double& v : p) {
    v = std::isnan(v) ? 0.0 : clip(v, hardness);
    all_zero = all_zero && v == 0.0;
  }
  if (all_zero) {
    if (load) {
      std::fill(p.begin(), p.end(), target);
    } else {
      for (std::size_t i = 0; i < n; ++i) t_[i] = std::max(0.0, w - s[i]);
      op_.apply(t_.data(), r_.data());
      double num = 0.0, den = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        num += t_[i] * (w - s[i]);
        den += t_[i] * r_[i];
      }
      const double alpha = num / den;
      for (std::size_t i = 0; i < n; ++i) p[i] = clip(alpha * t_[i], hardness);
    }
  }
  auto enforce_load = [&]() {
    double sum = 0.0;
    for (double v : p) sum += v;
    if (sum > 0.0) {
      const double f = target * static_cast<double>(n) / sum;
      for (double& v : p) v *= f;
    }
  };
  if (load) enforce_load();

  double g_old = 1.0;
  bool conjugate = false;  // δ of Polonsky & Keer: restart after a set change
  std::fill(t_.begin(), t_.end(), 0.0);
  int it = 0;
  for (;; ++it) {
    // Gap g = s − w + C p (D-7, README Eq. 6).
    op_.apply(p.data(), u_.data());
    if (load) {
      // w = mean of s + u over the loaded cells: makes the mean gap there zero.
      double sum = 0.0;
      std::size_t cnt = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (p[i] > 0.0) {
          sum += s[i] + u_[i];
          ++cnt;
        }
      w = sum / static_cast<double>(cnt);
    }
    for (std::size_t i = 0; i < n; ++i) g_[i] = s[i] - w + u_[i];
    res.error = kkt_residual(p, g_, hardness, c) / g_ref;
    if (res.error < opt.tolerance) {
      res.converged = true;
      break;
    }
    if (it >= opt.max_iterations) break;

    // CG set S = {0 < p < H}. If S is empty, or the gradient on S vanishes (e.g. an exact warm
    // start whose only defect is cells that must leave a bound), restart with the violating bound
    // cells added to S: t = g there, no conjugation.
    std::size_t free_count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      set_[i] = (p[i] > 0.0 && p[i] < hardness) ? kFree : kOut;
      free_count += set_[i];
    }
    double num = 0.0, den = 0.0;
    auto direction_and_step = [&]() {
      // Search direction t = g + δ (G/G_old) t on S (README Eq. 7), r = C t, τ = gᵀt / tᵀC t.
      double gg = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (set_[i] == kFree) gg += g_[i] * g_[i];
      const double beta = conjugate ? gg / g_old : 0.0;
      g_old = gg;
      for (std::size_t i = 0; i < n; ++i) t_[i] = set_[i] == kFree ? g_[i] + beta * t_[i] : 0.0;
      op_.apply(t_.data(), r_.data());
      if (load) {
        double sum = 0.0;
        std::size_t cnt = 0;
        for (std::size_t i = 0; i < n; ++i)
          if (set_[i] == kFree) {
            sum += r_[i];
            ++cnt;
          }
        const double mean = cnt > 0 ? sum / static_cast<double>(cnt) : 0.0;
        for (std::size_t i = 0; i < n; ++i) r_[i] -= mean;
      }
      num = 0.0;
      den = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (set_[i] == kFree) {
          num += g_[i] * t_[i];
          den += r_[i] * t_[i];
        }
    };
    if (free_count > 0) direction_and_step();
    bool released = false;
    if (!(den > 0.0)) {
      released = true;
      for (std::size_t i = 0; i < n; ++i)
        if ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0)) set_[i] = kFree;
      conjugate = false;
      direction_and_step();
    }
    if (!(den > 0.0)) {
      ++it;  // nothing left to move: stop; reported unconverged since ε ≥ tolerance
      break;
    }
    const double tau = num / den;
    // Step on S; release bound cells whose gap says so: p = 0 with g < 0, p = H with g > 0
    // (README Eq. 8); a release restarts the conjugate directions.
    for (std::size_t i = 0; i < n; ++i) {
      if (set_[i] == kFree) {
        p[i] = clip(p[i] - tau * t_[i], hardness);
      } else if ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0)) {
        p[i] = clip(p[i] - tau * g_[i], hardness);
        released = true;
      }
    }
    if (load) enforce_load();
    conjugate = !released;
  }
  res.iterations = it;
  res.approach = w;

  // Outputs (seed 001 Eq. 12; README Eq. 10).
  double force = 0.0, vp = 0.0, pmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    force += p[i];
    pmax = std::max(pmax, p[i]);
    if (p[i] > 0.0) ++res.contact_cells;
    if (p[i] == hardness) {
      ++res.plastic_cells;
      vp += std::max(0.0, -g_[i]);
    }
  }
  res.force = area * force;
  res.contact_area = area * static_cast<double>(res.contact_cells);
  res.plastic_volume = area * vp;
  res.max_pressure = pmax;
  if (opt.compute_stiffness && op_.boundary() == Boundary::Open) frozen_stiffness(p, opt, res);
  return res;
}

// k = dP/dw with the contact set frozen (README Eq. 11): on the elastic contact cells E
// (0 < p < H) solve C_EE Δp = 1 by CG; plastic cells stay at H, open cells at 0; k = ΔA Σ Δp.
// Then the sub-cell edge correction δk (README Eq. 13–15): stiffness = k_frozen + δk.
void ContactSolver::frozen_stiffness(const std::vector<double>& p, const SolverOptions& opt, ContactResult& res) {
  const std::size_t n = p.size();
  const double hardness = opt.hardness;
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    set_[i] = (p[i] > 0.0 && p[i] < hardness) ? kFree : kOut;
    m += set_[i];
  }
  dp_.assign(n, 0.0);
  if (m == 0) {
    res.stiffness = 0.0;
    res.frozen_stiffness = 0.0;
    res.stiffness_converged = true;
    return;
  }
  gap_ = g_;  // the converged gap (g_ is the CG residual below)
  // x = Δp, g_ = residual, t_ = direction, r_ = C t.
  std::fill(x_.begin(), x_.end(), 0.0);
  double rr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    g_[i] = set_[i] == kFree ? 1.0 : 0.0;
    t_[i] = g_[i];
    rr += g_[i];
  }
  const double stop = opt.stiffness_tolerance * opt.stiffness_tolerance * static_cast<double>(m);
  int it = 0;
  bool ok = rr <= stop;
  while (!ok && it < opt.stiffness_max_iterations) {
    op_.apply(t_.data(), r_.data());
    double tr = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (set_[i] == kFree) tr += t_[i] * r_[i];
    const double alpha = rr / tr;
    double rr_new = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (set_[i] == kFree) {
        x_[i] += alpha * t_[i];
        g_[i] -= alpha * r_[i];
        rr_new += g_[i] * g_[i];
      }
    ++it;
    ok = rr_new <= stop;
    const double beta = rr_new / rr;
    rr = rr_new;
    for (std::size_t i = 0; i < n; ++i) t_[i] = set_[i] == kFree ? g_[i] + beta * t_[i] : 0.0;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += x_[i];
  dp_ = x_;
  res.frozen_stiffness = op_.grid().cell_area() * sum;
  res.stiffness_converged = ok;
  res.stiffness_iterations = it;
  // Sub-cell contact edge (README Eq. 13–15): one more half-space product, u' = C dp.
  op_.apply(dp_.data(), r_.data());
  const EdgeCorrection edge = edge_correction(op_.grid(), op_.e_star(), res.approach, p, dp_, gap_, r_, hardness);
  res.edge_correction = edge.delta_k;
  res.stiffness = res.frozen_stiffness + edge.delta_k;
}

}  // namespace rollspec::contact
