// Imposed-total-load policy of the Polonsky–Keer core (pk_policies.hpp; README Eq. 17, 17a, 17b):
// load control on the open half-space with the pressure cap.
#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/contact/cell_loops.hpp"
#include "kernels/contact/pk_policies.hpp"

namespace rollspec::contact::detail {

namespace {
// The listed cells reach w_L = w + 0.2 (w − min s): position to position the approach moves by a
// few per cent of the interference, so L is rarely rebuilt (seed-002 strip: never), and L stays
// inside a 128² box of the 144² window (Eq. 3c; a margin of 0.5 listed 30 % more cells and needed
// the whole window's product).
constexpr double kListMargin = 0.2;
}  // namespace

ForcePolicy::ForcePolicy(const PkArrays& a, const Lists& lists, HalfSpaceOperator& op, BoxProduct& box,
                         const std::vector<double>& s, std::vector<double>& p, double total, double hint,
                         const SolverOptions& opt, ContactResult& res)
    : a_(a),
      l_(lists),
      op_(op),
      box_(box),
      s_(s),
      p_(p),
      total_(total),
      hint_(hint),
      hardness_(opt.hardness),
      c_(op.self_coefficient()),
      s_min_(*std::min_element(s.begin(), s.end())),
      precondition_(opt.precondition),
      nx_(op.grid().nx),
      res_(res),
      w_list_(std::numeric_limits<double>::infinity()) {}

double ForcePolicy::margin(double w) const { return w + kListMargin * std::max(w - s_min_, 0.0); }

// Listed cells L = {s_i < w_L} ∪ {p_i > 0} (Eq. 6a: only s_i < w can carry pressure); w_L ≥ w at
// every evaluation, else L is rebuilt. No estimate of w yet: every cell.
void ForcePolicy::build_list() {
  l_.listed.clear();
  for (std::size_t i = 0; i < s_.size(); ++i)
    if (s_[i] < w_list_ || p_[i] > 0.0) l_.listed.push_back(static_cast<std::uint32_t>(i));
  box_.set_cells(l_.listed);
}

void ForcePolicy::start() {
  if (std::isfinite(hint_) && hint_ > s_min_) w_list_ = margin(hint_);
  // The warm start clipped into [0, H]; cold: the interference at the hint, or uniform.
  double sum = 0.0;
  for (double& v : p_) {
    v = std::isnan(v) ? 0.0 : clip(v, hardness_);
    sum += v;
  }
  if (!(sum > 0.0))
    for (std::size_t i = 0; i < p_.size(); ++i) p_[i] = std::isfinite(w_list_) ? std::max(0.0, hint_ - s_[i]) : 1.0;
  build_list();
  const std::vector<std::uint32_t>& cells = l_.listed;
  const auto sums = block_reduce<2>(cells.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    for (const std::size_t i : Slice{cells.data(), lo, hi}) acc[p_[i] < hardness_ ? 0 : 1] += p_[i];
  });
  rescale(false, sums[0], sums[1]);
  for (const std::uint32_t i : cells) a_.t[i] = 0.0;
  l_.free.clear();  // t is zero off the last S
}

// Eq. 17b: the free cells scaled, p ← f p on 0 < p < H with f = (total − Σ_{p=H} p) / Σ_free p
// (cells pushed above H clipped back), until Σ p = total to 1e-15; if the saturated cells alone
// carry more than the load (or nothing is free), every cell is scaled instead. With `carry_u`
// the carried u = C (p − delta) is kept: u ← f u, delta ← p' − f p + f delta (C is linear).
// Returns true if delta changed beyond its own scaling (a cell capped, or saturated cells held).
bool ForcePolicy::rescale(bool carry_u, double free_sum, double capped_sum) {
  const std::vector<std::uint32_t>& cells = l_.listed;
  std::vector<double>& delta = l_.delta;
  bool any_capped = false;
  for (int round = 0; round < 64; ++round) {
    const double now = free_sum + capped_sum;
    if (!(now > 0.0) || std::fabs(now - total_) <= 1e-15 * total_) break;
    const bool free_only = free_sum > 0.0 && total_ > capped_sum;
    const double f = free_only ? (total_ - capped_sum) / free_sum : total_ / now;
    const auto r = block_reduce<3>(cells.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{cells.data(), lo, hi}) {
        const double old = p_[i];
        if (!free_only || old < hardness_) {
          const double v = f * old;
          p_[i] = std::min(v, hardness_);
          if (p_[i] != v) acc[0] += 1.0;
        }
        if (carry_u) {
          a_.u[i] *= f;
          delta[i] = (p_[i] - f * old) + f * delta[i];
        }
        acc[p_[i] < hardness_ ? 1 : 2] += p_[i];
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

// w (the multiplier: the mean of s + u over the free cells, else over the loaded ones), then
// g = s − w + u on L, G = Σ_S g², Σ_S g, and ε (Eq. 9 with g_ref = w − min s).
void ForcePolicy::evaluate() {
  const std::vector<std::uint32_t>& cells = l_.listed;
  const std::vector<double>& u = a_.u;
  const auto m = block_reduce<4>(cells.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    for (const std::size_t i : Slice{cells.data(), lo, hi})
      if (p_[i] > 0.0) {
        const bool is_free = p_[i] < hardness_;
        acc[is_free ? 0 : 2] += s_[i] + u[i];
        acc[is_free ? 1 : 3] += 1.0;
      }
  });
  w_ = m[1] > 0.0 ? m[0] / m[1] : (m[3] > 0.0 ? m[2] / m[3] : s_min_);
  g_ref_ = std::max(w_ - s_min_, 1e-300);
  const double w = w_;
  const auto e = block_reduce<3>(
      cells.size(), a_.part,
      [&](std::size_t lo, std::size_t hi, double* acc) {
        double emax = 0.0, sq = 0.0, sg = 0.0;
        for (const std::size_t i : Slice{cells.data(), lo, hi}) {
          const double gi = s_[i] - w + u[i];
          a_.g[i] = gi;
          emax = std::max(emax, std::fabs(p_[i] - clip(p_[i] - gi / c_, hardness_)));
          if (p_[i] > 0.0 && p_[i] < hardness_) {
            sq += gi * gi;
            sg += gi;
          }
        }
        acc[0] = emax, acc[1] = sq, acc[2] = sg;
      },
      1u);
  res_.error = c_ * e[0] / g_ref_;
  gg_ = e[1];
  g_sum_ = e[2];
}

// L must hold every cell with s < w (Eq. 6a): else list them (u on the new cells by a product).
// Then γ of Eq. 7b from the interference set A = {s < w} at the first w (fixed for the solve).
bool ForcePolicy::prepare() {
  bool fresh = false;
  if (!(w_ < w_list_)) {
    for (const std::uint32_t i : l_.free) a_.t[i] = 0.0;
    l_.free.clear();
    w_list_ = margin(w_);
    build_list();
    refresh();
    fresh = true;
    conjugate_ = false;
    for (const std::uint32_t i : l_.listed) a_.t[i] = 0.0;
    evaluate();
    gamma_ = 0.0;
  }
  if (gamma_ == 0.0) {
    std::size_t a = 0;
    for (const std::uint32_t i : l_.listed) a += s_[i] < w_ ? 1 : 0;
    gamma_ = precondition_gamma(std::max<std::size_t>(a, 1));
  }
  return fresh;
}

// S = {0 < p < H} as a list (increasing); t cleared on the cells that left it.
void ForcePolicy::collect_free() {
  for (const std::uint32_t i : l_.free)
    if (!(p_[i] > 0.0 && p_[i] < hardness_)) a_.t[i] = 0.0;
  l_.free.clear();
  for (const std::uint32_t i : l_.listed) {
    const bool is_free = p_[i] > 0.0 && p_[i] < hardness_;
    a_.set[i] = is_free ? kFree : kOut;
    if (is_free) l_.free.push_back(i);
  }
}

// Eq. 17a: z = M g on S, projected to zero sum over S (Σ_S g = 0 by the choice of w, so
// G = Σ_S g (z − z̄)); t = z − z̄ + δ (G/G_old) t, projected again (after a set change the old
// t has lost its zero sum); τ = Σ_S g t / Σ_S (C t) t. `project` false: the release fallback
// (the violating bound cells added to S alone may have no zero-sum direction).
void ForcePolicy::direction_and_step(bool project, double& num, double& den) {
  const std::vector<std::uint32_t>& free = l_.free;
  std::vector<double>& t = a_.t;
  const std::size_t m = free.size();
  double zz = gg_;
  if (precondition_) zz = apply_preconditioner(free, a_.set, a_.g, a_.x, gamma_, nx_, a_.part);
  const std::vector<double>& z = precondition_ ? a_.x : a_.g;
  double z_mean = 0.0;
  if (project) {
    for (const std::uint32_t i : free) z_mean += z[i];
    z_mean /= static_cast<double>(m);
  }
  for (int attempt = 0; attempt < 2; ++attempt) {
    const double G = zz - z_mean * g_sum_;
    const double beta = conjugate_ ? G / g_old_ : 0.0;
    double t_sum = 0.0;
    for (const std::uint32_t i : free) {
      t[i] = (z[i] - z_mean) + beta * t[i];
      t_sum += t[i];
    }
    if (project) {
      const double t_mean = t_sum / static_cast<double>(m);
      for (const std::uint32_t i : free) t[i] -= t_mean;
    }
    num = 0.0;
    for (const std::uint32_t i : free) num += a_.g[i] * t[i];
    g_old_ = G;
    // Not a descent direction after a set change: restart (δ = 0).
    if (num > 0.0 || !conjugate_) break;
    conjugate_ = false;
  }
  box_.apply(t.data(), a_.r.data());
  den = 0.0;
  for (const std::uint32_t i : free) den += a_.r[i] * t[i];
}

void ForcePolicy::direction(double& num, double& den) {
  collect_free();
  if (l_.free.size() > 1) direction_and_step(true, num, den);
}

void ForcePolicy::release(double& num, double& den) {
  const std::vector<double>& g = a_.g;
  gg_ = 0.0;
  g_sum_ = 0.0;
  for (const std::uint32_t i : l_.listed)
    if (a_.set[i] != kFree && ((p_[i] == 0.0 && g[i] < 0.0) || (p_[i] == hardness_ && g[i] > 0.0))) {
      a_.set[i] = kFree;
      a_.t[i] = 0.0;
    }
  l_.free.clear();
  for (const std::uint32_t i : l_.listed)
    if (a_.set[i] == kFree) {
      l_.free.push_back(i);
      gg_ += g[i] * g[i];
      g_sum_ += g[i];
    }
  conjugate_ = false;
  if (!l_.free.empty()) direction_and_step(false, num, den);
}

// u = C p after a step that was not exactly −τ t: carried (−τ C t, times f) plus C delta by direct
// sums while that is cheaper than a product on the box (Eq. 3b); true if u is then exact.
bool ForcePolicy::carry(bool changed) {
  if (!changed) return true;
  const std::vector<std::uint32_t>& cells = l_.listed;
  bool u_valid = false;
  l_.touched.clear();
  for (const std::uint32_t i : cells)
    if (l_.delta[i] != 0.0) l_.touched.push_back(i);
  if (static_cast<double>(l_.touched.size()) * static_cast<double>(cells.size()) < box_.fft_cost()) {
    op_.apply_direct(l_.delta.data(), l_.touched, cells, a_.x.data());
    for (const std::uint32_t i : cells) a_.u[i] += a_.x[i];
    u_valid = true;
  }
  for (const std::uint32_t i : l_.touched) l_.delta[i] = 0.0;
  return u_valid;
}

// Step (Eq. 7, 8); delta = p_new − (p − τ t) where the step was not exactly −τ t; Σ p after it,
// then the load balance (17b) and the carried u.
bool ForcePolicy::step(double tau, bool released) {
  const std::vector<std::uint32_t>& cells = l_.listed;
  const std::vector<double>& g = a_.g;
  const std::vector<double>& t = a_.t;
  const std::vector<double>& r = a_.r;
  std::vector<double>& delta = l_.delta;
  const auto moved = block_reduce<4>(cells.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    bool freed = false, clipped = false;
    for (const std::size_t i : Slice{cells.data(), lo, hi}) {
      if (a_.set[i] == kFree) {
        const double step = p_[i] - tau * t[i];
        p_[i] = clip(step, hardness_);
        if (p_[i] != step) {
          delta[i] = p_[i] - step;
          clipped = true;
        }
      } else if ((p_[i] == 0.0 && g[i] < 0.0) || (p_[i] == hardness_ && g[i] > 0.0)) {
        const double before = p_[i];
        p_[i] = clip(p_[i] - tau * g[i], hardness_);
        delta[i] = p_[i] - before;
        freed = true;
      }
      a_.u[i] -= tau * r[i];
      acc[p_[i] < hardness_ ? 2 : 3] += p_[i];
    }
    acc[0] = freed ? 1.0 : 0.0;
    acc[1] = clipped ? 1.0 : 0.0;
  });
  released = released || moved[0] > 0.0;
  const bool capped = rescale(true, moved[2], moved[3]);  // Eq. 17b
  const bool u_valid = carry(released || moved[1] > 0.0 || capped);
  // Unlike (7), a release does not restart the conjugate directions: a direction that is no
  // longer one of descent is restarted in direction_and_step instead (seed-002 strip: 32.6
  // iterations per position against 35 with the restart).
  conjugate_ = true;
  return u_valid;
}

}  // namespace rollspec::contact::detail
