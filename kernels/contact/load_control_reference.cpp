// Plain reference: ContactSolver::solve_at_force as first written (load control on the open
// half-space with the cap; README Eq. 17, 17a, 17b), one loop; its lambdas are now the member
// functions of ForceReference (same statements, same order). The solver uses the shared
// Polonsky–Keer core (polonsky_keer.hpp) instead; the doctests (test_pk_core.cpp) check the two
// give the same bits. Keep its arithmetic unchanged.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/contact/cell_loops.hpp"
#include "kernels/contact/contact_solver.hpp"

namespace rollspec::contact {

using namespace detail;

namespace {
// The listed cells reach w_L = w + 0.2 (w − min s): position to position the approach moves by a
// few per cent of the interference, so L is rarely rebuilt (seed-002 strip: never), and L stays
// inside a 128² box of the 144² window (Eq. 3c; a margin of 0.5 listed 30 % more cells and needed
// the whole window's product).
constexpr double kListMarginReference = 0.2;

// The state of one solve_at_force_reference: the solve's inputs, the solver's work arrays (by
// reference, under their member names) and the loop's scalars; the member functions are the
// loop's pieces.
struct ForceReference {
  const std::vector<double>& s;
  std::vector<double>& p;
  const SolverOptions& opt;
  ContactResult& res;
  const double hardness, c, total, s_min;
  const std::size_t n, nx;
  HalfSpaceOperator& op_;
  std::unique_ptr<BoxProduct>& box_;
  std::vector<double>& u_;
  std::vector<double>& g_;
  std::vector<double>& t_;
  std::vector<double>& r_;
  std::vector<double>& x_;
  std::vector<double>& part_;
  std::vector<double>& delta_;
  std::vector<unsigned char>& set_;
  std::vector<std::uint32_t>& listed_;
  std::vector<std::uint32_t>& touched_;
  const std::vector<std::uint32_t>& cells;  // L
  std::vector<std::uint32_t>& free;         // S as a list (increasing)

  // Listed cells L = {s_i < w_L} ∪ {p_i > 0} (Eq. 6a: only s_i < w can carry pressure); w_L ≥ w at
  // every evaluation, else L is rebuilt. No estimate of w yet: every cell.
  double w_list = std::numeric_limits<double>::infinity();
  bool u_valid = false;
  bool precondition = false;
  double gamma = 0.0;
  double g_old = 1.0, w = 0.0, g_ref = 1.0;
  bool conjugate = false;
  double gg = 0.0, g_sum = 0.0;
  double num = 0.0, den = 0.0;
  int it = 0;

  double margin(double w_at) const { return w_at + kListMarginReference * std::max(w_at - s_min, 0.0); }

  void build_list() {
    listed_.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (s[i] < w_list || p[i] > 0.0) listed_.push_back(static_cast<std::uint32_t>(i));
    box_->set_cells(listed_);
  }

  // Start: the warm start clipped into [0, H]; cold: the interference at the hint, or uniform.
  void start(double hint) {
    double sum = 0.0;
    for (double& v : p) {
      v = std::isnan(v) ? 0.0 : clip(v, hardness);
      sum += v;
    }
    if (!(sum > 0.0))
      for (std::size_t i = 0; i < n; ++i) p[i] = std::isfinite(w_list) ? std::max(0.0, hint - s[i]) : 1.0;
    build_list();
    const auto sums = block_reduce<2>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{cells.data(), lo, hi}) acc[p[i] < hardness ? 0 : 1] += p[i];
    });
    rescale(false, sums[0], sums[1]);
  }

  // Eq. 17b: the free cells scaled, p ← f p on 0 < p < H with f = (total − Σ_{p=H} p) / Σ_free p
  // (cells pushed above H clipped back), until Σ p = total to 1e-15; if the saturated cells alone
  // carry more than the load (or nothing is free), every cell is scaled instead. With `carry_u`
  // the carried u = C (p − delta_) is kept: u ← f u, delta_ ← p' − f p + f delta_ (C is linear).
  // Returns true if delta_ changed beyond its own scaling (a cell capped, or saturated cells held).
  bool rescale(bool carry_u, double free_sum, double capped_sum) {
    bool any_capped = false;
    for (int round = 0; round < 64; ++round) {
      const double now = free_sum + capped_sum;
      if (!(now > 0.0) || std::fabs(now - total) <= 1e-15 * total) break;
      const bool free_only = free_sum > 0.0 && total > capped_sum;
      const double f = free_only ? (total - capped_sum) / free_sum : total / now;
      const auto r = block_reduce<3>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
        for (const std::size_t i : Slice{cells.data(), lo, hi}) {
          const double old = p[i];
          if (!free_only || old < hardness) {
            const double v = f * old;
            p[i] = std::min(v, hardness);
            if (p[i] != v) acc[0] += 1.0;
          }
          if (carry_u) {
            u_[i] *= f;
            delta_[i] = (p[i] - f * old) + f * delta_[i];
          }
          acc[p[i] < hardness ? 1 : 2] += p[i];
        }
      });
      any_capped = any_capped || (free_only && capped_sum > 0.0);
      free_sum = r[1];
      capped_sum = r[2];
      any_capped = any_capped || r[0] > 0.0;
      if (r[0] == 0.0 && free_only) break;  // Σ p = total to rounding
    }
    return any_capped;
  }

  // The product on L (box, Eq. 3c).
  void product(const double* v, double* out) { box_->apply(v, out); }

  // w (the multiplier: the mean of s + u over the free cells, else over the loaded ones), then
  // g = s − w + u on L, the CG set S, G = Σ_S g², and ε (Eq. 9 with g_ref = w − min s).
  void evaluate() {
    const auto m = block_reduce<4>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{cells.data(), lo, hi})
        if (p[i] > 0.0) {
          const bool is_free = p[i] < hardness;
          acc[is_free ? 0 : 2] += s[i] + u_[i];
          acc[is_free ? 1 : 3] += 1.0;
        }
    });
    w = m[1] > 0.0 ? m[0] / m[1] : (m[3] > 0.0 ? m[2] / m[3] : s_min);
    g_ref = std::max(w - s_min, 1e-300);
    const auto e = block_reduce<3>(
        cells.size(), part_,
        [&](std::size_t lo, std::size_t hi, double* acc) {
          double emax = 0.0, sq = 0.0, sg = 0.0;
          for (const std::size_t i : Slice{cells.data(), lo, hi}) {
            const double gi = s[i] - w + u_[i];
            g_[i] = gi;
            emax = std::max(emax, std::fabs(p[i] - clip(p[i] - gi / c, hardness)));
            if (p[i] > 0.0 && p[i] < hardness) {
              sq += gi * gi;
              sg += gi;
            }
          }
          acc[0] = emax, acc[1] = sq, acc[2] = sg;
        },
        1u);
    res.error = c * e[0] / g_ref;
    gg = e[1];
    g_sum = e[2];
  }

  // S = {0 < p < H} as a list; t_ cleared on the cells that left it.
  void collect_free() {
    for (const std::uint32_t i : free)
      if (!(p[i] > 0.0 && p[i] < hardness)) t_[i] = 0.0;
    free.clear();
    for (const std::uint32_t i : cells) {
      const bool is_free = p[i] > 0.0 && p[i] < hardness;
      set_[i] = is_free ? kFree : kOut;
      if (is_free) free.push_back(i);
    }
  }

  // L must hold every cell with s < w (Eq. 6a): else list them (u on the new cells by a product).
  void relist() {
    for (const std::uint32_t i : free) t_[i] = 0.0;
    free.clear();
    w_list = margin(w);
    build_list();
    product(p.data(), u_.data());
    conjugate = false;
    for (const std::uint32_t i : cells) t_[i] = 0.0;
    evaluate();
    gamma = 0.0;
  }

  // Eq. 17a: z = M g on S, projected to zero sum over S (Σ_S g = 0 by the choice of w, so
  // G = Σ_S g (z − z̄)); t = z − z̄ + δ (G/G_old) t, projected again (after a set change the old
  // t has lost its zero sum); τ = Σ_S g t / Σ_S (C t) t. `project` false: the release fallback
  // (the violating bound cells added to S alone may have no zero-sum direction).
  void direction_and_step(bool project) {
    const std::size_t m = free.size();
    double zz = gg;
    if (precondition) zz = apply_preconditioner(free, set_, g_, x_, gamma, nx, part_);
    const std::vector<double>& z = precondition ? x_ : g_;
    double z_mean = 0.0;
    if (project) {
      for (const std::uint32_t i : free) z_mean += z[i];
      z_mean /= static_cast<double>(m);
    }
    for (int attempt = 0; attempt < 2; ++attempt) {
      const double G = zz - z_mean * g_sum;
      const double beta = conjugate ? G / g_old : 0.0;
      double t_sum = 0.0;
      for (const std::uint32_t i : free) {
        t_[i] = (z[i] - z_mean) + beta * t_[i];
        t_sum += t_[i];
      }
      if (project) {
        const double t_mean = t_sum / static_cast<double>(m);
        for (const std::uint32_t i : free) t_[i] -= t_mean;
      }
      num = 0.0;
      for (const std::uint32_t i : free) num += g_[i] * t_[i];
      g_old = G;
      // Not a descent direction after a set change: restart (δ = 0).
      if (num > 0.0 || !conjugate) break;
      conjugate = false;
    }
    product(t_.data(), r_.data());
    den = 0.0;
    for (const std::uint32_t i : free) den += r_[i] * t_[i];
  }

  // The release fallback: the violating bound cells added to S, no conjugation, no projection.
  void release_and_step() {
    gg = 0.0;
    g_sum = 0.0;
    for (const std::uint32_t i : cells)
      if (set_[i] != kFree && ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0))) {
        set_[i] = kFree;
        t_[i] = 0.0;
      }
    free.clear();
    for (const std::uint32_t i : cells)
      if (set_[i] == kFree) {
        free.push_back(i);
        gg += g_[i] * g_[i];
        g_sum += g_[i];
      }
    conjugate = false;
    if (!free.empty()) direction_and_step(false);
  }

  // Step (Eq. 7, 8); delta_ = p_new − (p − τ t) where the step was not exactly −τ t; Σ p after it.
  void take_step(double tau, bool released) {
    const auto moved = block_reduce<4>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      bool freed = false, clipped = false;
      for (const std::size_t i : Slice{cells.data(), lo, hi}) {
        if (set_[i] == kFree) {
          const double step = p[i] - tau * t_[i];
          p[i] = clip(step, hardness);
          if (p[i] != step) {
            delta_[i] = p[i] - step;
            clipped = true;
          }
        } else if ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0)) {
          const double before = p[i];
          p[i] = clip(p[i] - tau * g_[i], hardness);
          delta_[i] = p[i] - before;
          freed = true;
        }
        u_[i] -= tau * r_[i];
        acc[p[i] < hardness ? 2 : 3] += p[i];
      }
      acc[0] = freed ? 1.0 : 0.0;
      acc[1] = clipped ? 1.0 : 0.0;
    });
    released = released || moved[0] > 0.0;
    const bool capped = rescale(true, moved[2], moved[3]);  // Eq. 17b
    // u = C p: carried (−τ C t, times f) plus C delta_ by direct sums while that is cheaper (Eq. 3b).
    if (released || moved[1] > 0.0 || capped) {
      touched_.clear();
      for (const std::uint32_t i : cells)
        if (delta_[i] != 0.0) touched_.push_back(i);
      if (static_cast<double>(touched_.size()) * static_cast<double>(cells.size()) < box_->fft_cost()) {
        op_.apply_direct(delta_.data(), touched_, cells, x_.data());
        for (const std::uint32_t i : cells) u_[i] += x_[i];
        u_valid = true;
      } else {
        u_valid = false;
      }
      for (const std::uint32_t i : touched_) delta_[i] = 0.0;
    } else {
      u_valid = true;
    }
    // Unlike (7), a release does not restart the conjugate directions: a direction that is no
    // longer one of descent is restarted in direction_and_step instead (seed-002 strip: 32.6
    // iterations per position against 35 with the restart).
    conjugate = true;
  }

  void iterate() {
    for (;; ++it) {
      bool fresh = false;
      if (!u_valid) {
        product(p.data(), u_.data());
        fresh = true;
      }
      evaluate();
      // L must hold every cell with s < w (Eq. 6a): else list them (u on the new cells by a product).
      if (!(w < w_list)) {
        relist();
        fresh = true;
      }
      if (gamma == 0.0) {
        // γ of Eq. 7b from the interference set A = {s < w} at the first w (fixed for the solve).
        std::size_t a = 0;
        for (const std::uint32_t i : cells) a += s[i] < w ? 1 : 0;
        gamma = precondition_gamma(std::max<std::size_t>(a, 1));
      }
      if ((res.error < opt.tolerance || it >= opt.max_iterations) && !fresh) {
        product(p.data(), u_.data());  // decide on the exact gap
        fresh = true;
        evaluate();
      }
      if (res.error < opt.tolerance) {
        res.converged = true;
        break;
      }
      if (it >= opt.max_iterations) break;
      collect_free();

      num = 0.0;
      den = 0.0;
      if (free.size() > 1) direction_and_step(true);
      bool released = false;
      if (!(den > 0.0)) {
        released = true;
        release_and_step();
      }
      if (!(den > 0.0)) {
        ++it;  // nothing left to move: stop, unconverged (ε ≥ tolerance)
        if (!fresh) {
          product(p.data(), u_.data());
          evaluate();
        }
        break;
      }
      const double tau = num / den;
      take_step(tau, released);
    }
  }

  // Outputs (seed 001 Eq. 12; README Eq. 10): g is exact on L (a fresh product), p = 0 off L.
  void outputs(double area) {
    res.iterations = it;
    res.approach = w;
    double f_sum = 0.0, vp = 0.0, pmax = 0.0;
    for (const std::uint32_t i : cells) {
      f_sum += p[i];
      pmax = std::max(pmax, p[i]);
      if (p[i] > 0.0) ++res.contact_cells;
      if (p[i] == hardness) {
        ++res.plastic_cells;
        vp += std::max(0.0, -g_[i]);
      }
    }
    res.force = area * f_sum;
    res.contact_area = area * static_cast<double>(res.contact_cells);
    res.plastic_volume = area * vp;
    res.max_pressure = pmax;
  }
};

}  // namespace

ContactResult ContactSolver::solve_at_force_reference(const std::vector<double>& s, double force,
                                                      std::vector<double>& p, const SolverOptions& opt, double hint) {
  const Grid& grid = op_.grid();
  const std::size_t n = grid.size();
  const double area = grid.cell_area();
  const double hardness = opt.hardness;
  const double c = op_.self_coefficient();
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
  const double s_min = *std::min_element(s.begin(), s.end());
  ContactResult res;
  if (force == 0.0) {  // first contact, no pressure: D-7 holds exactly
    std::fill(p.begin(), p.end(), 0.0);
    res.approach = s_min;
    res.converged = true;
    return res;
  }
  if (!box_) box_ = std::make_unique<BoxProduct>(op_);
  if (delta_.size() != n) delta_.assign(n, 0.0);

  ForceReference ref{s,  p,  opt, res, hardness, c,     total,  s_min, n,       grid.nx,  op_,     box_,
                     u_, g_, t_,  r_,  x_,       part_, delta_, set_,  listed_, touched_, listed_, free_};
  if (std::isfinite(hint) && hint > s_min) ref.w_list = ref.margin(hint);
  ref.start(hint);

  ref.precondition = opt.precondition;
  for (const std::uint32_t i : listed_) t_[i] = 0.0;
  free_.clear();  // t_ is zero off the last S
  ref.iterate();
  ref.outputs(area);
  return res;
}

}  // namespace rollspec::contact
