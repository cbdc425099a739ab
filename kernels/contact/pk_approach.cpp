// Imposed-approach policy of the Polonsky–Keer core (pk_policies.hpp; README Eq. 6–10, 6a, 7a, 7b),
// with the periodic mean-pressure variant of solve_load.
#include <algorithm>
#include <cmath>
#include <utility>

#include "kernels/contact/cell_loops.hpp"
#include "kernels/contact/pk_policies.hpp"

namespace rollspec::contact::detail {

ApproachPolicy::ApproachPolicy(const PkArrays& a, Product product, const std::vector<double>& s, std::vector<double>& p,
                               const std::vector<std::uint32_t>& cells, double target, bool load, double g_ref,
                               double c, std::size_t active, std::size_t nx, const SolverOptions& opt,
                               ContactResult& res)
    : a_(a),
      product_(std::move(product)),
      s_(s),
      p_(p),
      cells_(cells),
      target_(target),
      hardness_(opt.hardness),
      c_(c),
      g_ref_(g_ref),
      gamma_(precondition_gamma(active)),
      load_(load),
      precondition_(!load && opt.precondition),
      n_(s.size()),
      nx_(nx),
      res_(res),
      w_(target) {}

bool ApproachPolicy::start(bool all_zero) {
  bool u_valid = false;
  if (all_zero) {
    if (load_) {
      std::fill(p_.begin(), p_.end(), target_);
    } else {
      // The best multiple of the rigid interference (one line search of Eq. 7).
      std::vector<double>& t = a_.t;
      std::vector<double>& r = a_.r;
      const double w = w_;
      for (std::size_t i = 0; i < n_; ++i) t[i] = std::max(0.0, w - s_[i]);
      product_(t.data(), r.data());
      const auto nd = block_reduce<2>(n_, a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
        for (std::size_t i = lo; i < hi; ++i) {
          acc[0] += t[i] * (w - s_[i]);
          acc[1] += t[i] * r[i];
        }
      });
      const double alpha = nd[0] / nd[1];
      bool clipped = false;
      for (std::size_t i = 0; i < n_; ++i) {
        p_[i] = clip(alpha * t[i], hardness_);
        a_.u[i] = alpha * r[i];
        clipped = clipped || p_[i] != alpha * t[i];
      }
      u_valid = !clipped;
    }
  }
  if (load_) enforce_load();
  // The iteration visits `cells` only: elsewhere p = 0, t = 0 and g ≥ s − w > 0 needs no u (Eq. 6a).
  std::fill(a_.set.begin(), a_.set.end(), kOut);
  std::fill(a_.t.begin(), a_.t.end(), 0.0);
  return u_valid;
}

void ApproachPolicy::enforce_load() {
  double sum = 0.0;
  for (double v : p_) sum += v;
  if (sum > 0.0) {
    const double f = target_ * static_cast<double>(n_) / sum;
    for (double& v : p_) v *= f;
  }
}

void ApproachPolicy::refresh() { u_full_ = product_(p_.data(), a_.u.data()); }

// Gap g = s − w + u (D-7, README Eq. 6), the CG set S = {0 < p < H}, G = Σ_S g², and ε (Eq. 9).
void ApproachPolicy::evaluate() {
  const std::vector<double>& u = a_.u;
  if (load_) {
    // w = mean of s + u over the loaded cells: makes the mean gap there zero.
    double sum = 0.0;
    std::size_t cnt = 0;
    for (std::size_t i = 0; i < n_; ++i)
      if (p_[i] > 0.0) {
        sum += s_[i] + u[i];
        ++cnt;
      }
    w_ = sum / static_cast<double>(cnt);
  }
  const double w = w_;
  const auto e = block_reduce<3>(
      cells_.size(), a_.part,
      [&](std::size_t lo, std::size_t hi, double* acc) {
        double emax = 0.0, sum = 0.0, count = 0.0;
        for (const std::size_t i : Slice{cells_.data(), lo, hi}) {
          const double gi = s_[i] - w + u[i];
          a_.g[i] = gi;
          emax = std::max(emax, std::fabs(p_[i] - clip(p_[i] - gi / c_, hardness_)));
          const bool is_free = p_[i] > 0.0 && p_[i] < hardness_;
          a_.set[i] = is_free ? kFree : kOut;
          if (is_free) {
            sum += gi * gi;
            count += 1.0;
          }
        }
        acc[0] = emax, acc[1] = sum, acc[2] = count;
      },
      1u);
  res_.error = c_ * e[0] / g_ref_;
  gg_ = e[1];
  free_count_ = static_cast<std::size_t>(e[2]);
}

// Search direction t = z + δ (G/G_old) t on S, z = M g (README Eq. 7, 7b), r = C t (mean-free on
// S in load control), τ = gᵀt / tᵀC t.
void ApproachPolicy::direction_and_step(double& num, double& den) {
  std::vector<double>& t = a_.t;
  std::vector<double>& r = a_.r;
  const std::vector<double>& g = a_.g;
  const std::vector<unsigned char>& set = a_.set;
  if (precondition_) gg_ = apply_preconditioner(cells_, set, g, a_.x, gamma_, nx_, a_.part);
  const std::vector<double>& z = precondition_ ? a_.x : g;
  const double beta = conjugate_ ? gg_ / g_old_ : 0.0;
  g_old_ = gg_;
  block_reduce<0>(cells_.size(), a_.part, [&](std::size_t lo, std::size_t hi, double*) {
    for (const std::size_t i : Slice{cells_.data(), lo, hi}) t[i] = set[i] == kFree ? z[i] + beta * t[i] : 0.0;
  });
  product_(t.data(), r.data());
  if (load_) {
    double sum = 0.0;
    std::size_t cnt = 0;
    for (std::size_t i = 0; i < n_; ++i)
      if (set[i] == kFree) {
        sum += r[i];
        ++cnt;
      }
    const double mean = cnt > 0 ? sum / static_cast<double>(cnt) : 0.0;
    for (std::size_t i = 0; i < n_; ++i) r[i] -= mean;
  }
  const auto nd = block_reduce<2>(cells_.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    for (const std::size_t i : Slice{cells_.data(), lo, hi})
      if (set[i] == kFree) {
        acc[0] += g[i] * t[i];
        acc[1] += r[i] * t[i];
      }
  });
  num = nd[0];
  den = nd[1];
}

void ApproachPolicy::direction(double& num, double& den) {
  if (free_count_ > 0) direction_and_step(num, den);
}

// S empty, or the gradient on S vanishes (e.g. an exact warm start whose only defect is cells that
// must leave a bound): the violating bound cells join S, t = g there, no conjugation.
void ApproachPolicy::release(double& num, double& den) {
  const std::vector<double>& g = a_.g;
  const auto e = block_reduce<1>(cells_.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    for (const std::size_t i : Slice{cells_.data(), lo, hi}) {
      if ((p_[i] == 0.0 && g[i] < 0.0) || (p_[i] == hardness_ && g[i] > 0.0)) a_.set[i] = kFree;
      if (a_.set[i] == kFree) acc[0] += g[i] * g[i];
    }
  });
  gg_ = e[0];
  conjugate_ = false;
  direction_and_step(num, den);
}

// Step on S; release bound cells whose gap says so: p = 0 with g < 0, p = H with g > 0 (README
// Eq. 8); a release restarts the conjugate directions. While the step is exactly −τ t (nothing
// clipped, nothing released) the displacement follows as u − τ C t (Eq. 7a).
bool ApproachPolicy::step(double tau, bool released) {
  const std::vector<double>& g = a_.g;
  const std::vector<double>& t = a_.t;
  const std::vector<double>& r = a_.r;
  std::vector<double>& u = a_.u;
  const auto moved = block_reduce<2>(cells_.size(), a_.part, [&](std::size_t lo, std::size_t hi, double* acc) {
    bool clipped = false, freed = false;
    for (const std::size_t i : Slice{cells_.data(), lo, hi}) {
      if (a_.set[i] == kFree) {
        const double step = p_[i] - tau * t[i];
        p_[i] = clip(step, hardness_);
        clipped = clipped || p_[i] != step;
      } else if ((p_[i] == 0.0 && g[i] < 0.0) || (p_[i] == hardness_ && g[i] > 0.0)) {
        p_[i] = clip(p_[i] - tau * g[i], hardness_);
        freed = true;
      }
      u[i] -= tau * r[i];
    }
    acc[0] = clipped ? 1.0 : 0.0;
    acc[1] = freed ? 1.0 : 0.0;
  });
  released = released || moved[1] > 0.0;
  const bool u_valid = !load_ && !released && moved[0] == 0.0;
  u_full_ = false;
  if (load_) enforce_load();
  conjugate_ = !released;
  return u_valid;
}

}  // namespace rollspec::contact::detail
