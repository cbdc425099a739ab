// Plain reference: ContactSolver::run as first written (displacement control and the periodic
// solve_load; README Eq. 6–10, 6a, 7a, 7b, 16), one loop; its lambdas are now the member functions
// of ApproachReference (same statements, same order). The solver uses the shared Polonsky–Keer
// core (polonsky_keer.hpp) instead; the doctests (test_pk_core.cpp) check the two give the same
// bits. Keep its arithmetic unchanged.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "kernels/contact/cell_loops.hpp"
#include "kernels/contact/contact_solver.hpp"

namespace rollspec::contact {

using namespace detail;

namespace {

// The state of one run_reference: the solve's inputs, the solver's work arrays (by reference,
// under their member names) and the loop's scalars; the member functions are the loop's pieces.
struct ApproachReference {
  const std::vector<double>& s;
  std::vector<double>& p;
  const SolverOptions& opt;
  ContactResult& res;
  double& w;
  const double target, g_ref, hardness, c;
  const bool load;
  const std::size_t n, nx;
  HalfSpaceOperator& op_;
  std::vector<double>& u_;
  std::vector<double>& g_;
  std::vector<double>& t_;
  std::vector<double>& r_;
  std::vector<double>& x_;
  std::vector<double>& part_;
  std::vector<unsigned char>& set_;
  const std::vector<std::uint32_t>& cells;
  // C v on A: by direct sums while they are cheaper (Eq. 3b), else everywhere by DC-FFT. True if
  // the product was the full one.
  std::function<bool(const double*, double*)> product;

  // u_ = C p is kept up to date by the step itself while no cell is clipped or released
  // (README Eq. 7a): then an iteration needs one half-space product, not two.
  bool u_valid = false;
  bool u_full = false;  // u_ = C p on every cell (not only on A, not carried)
  bool precondition = false;
  double gamma = 0.0;
  double g_old = 1.0;
  bool conjugate = false;  // δ of Polonsky & Keer: restart after a set change
  double gg = 0.0;         // Σ_S g_i² on the CG set of this iteration
  std::size_t free_count = 0;
  double num = 0.0, den = 0.0;
  int it = 0;

  // Cold start in displacement control: the best multiple of the rigid interference (one line
  // search); in load control uniform pressure.
  void cold_start() {
    if (load) {
      std::fill(p.begin(), p.end(), target);
    } else {
      for (std::size_t i = 0; i < n; ++i) t_[i] = std::max(0.0, w - s[i]);
      product(t_.data(), r_.data());
      const auto nd = block_reduce<2>(n, part_, [&](std::size_t lo, std::size_t hi, double* acc) {
        for (std::size_t i = lo; i < hi; ++i) {
          acc[0] += t_[i] * (w - s[i]);
          acc[1] += t_[i] * r_[i];
        }
      });
      const double alpha = nd[0] / nd[1];
      bool clipped = false;
      for (std::size_t i = 0; i < n; ++i) {
        p[i] = clip(alpha * t_[i], hardness);
        u_[i] = alpha * r_[i];
        clipped = clipped || p[i] != alpha * t_[i];
      }
      u_valid = !clipped;
    }
  }

  void enforce_load() {
    double sum = 0.0;
    for (double v : p) sum += v;
    if (sum > 0.0) {
      const double f = target * static_cast<double>(n) / sum;
      for (double& v : p) v *= f;
    }
  }

  // Gap g = s − w + u (D-7, README Eq. 6), the CG set S = {0 < p < H}, G = Σ_S g², and ε (Eq. 9).
  void evaluate() {
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
    const auto e = block_reduce<3>(
        cells.size(), part_,
        [&](std::size_t lo, std::size_t hi, double* acc) {
          double emax = 0.0, sum = 0.0, count = 0.0;
          for (const std::size_t i : Slice{cells.data(), lo, hi}) {
            const double gi = s[i] - w + u_[i];
            g_[i] = gi;
            emax = std::max(emax, std::fabs(p[i] - clip(p[i] - gi / c, hardness)));
            const bool is_free = p[i] > 0.0 && p[i] < hardness;
            set_[i] = is_free ? kFree : kOut;
            if (is_free) {
              sum += gi * gi;
              count += 1.0;
            }
          }
          acc[0] = emax, acc[1] = sum, acc[2] = count;
        },
        1u);
    res.error = c * e[0] / g_ref;
    gg = e[1];
    free_count = static_cast<std::size_t>(e[2]);
  }

  void direction_and_step() {
    // Search direction t = g + δ (G/G_old) t on S (README Eq. 7), r = C t, τ = gᵀt / tᵀC t.
    if (precondition) gg = apply_preconditioner(cells, set_, g_, x_, gamma, nx, part_);
    const std::vector<double>& z = precondition ? x_ : g_;
    const double beta = conjugate ? gg / g_old : 0.0;
    g_old = gg;
    block_reduce<0>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double*) {
      for (const std::size_t i : Slice{cells.data(), lo, hi}) t_[i] = set_[i] == kFree ? z[i] + beta * t_[i] : 0.0;
    });
    product(t_.data(), r_.data());
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
    const auto nd = block_reduce<2>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{cells.data(), lo, hi})
        if (set_[i] == kFree) {
          acc[0] += g_[i] * t_[i];
          acc[1] += r_[i] * t_[i];
        }
    });
    num = nd[0];
    den = nd[1];
  }

  // The restart of the iteration below: the violating bound cells added to S, t = g there, no
  // conjugation.
  void release_and_step() {
    const auto e = block_reduce<1>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      for (const std::size_t i : Slice{cells.data(), lo, hi}) {
        if ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0)) set_[i] = kFree;
        if (set_[i] == kFree) acc[0] += g_[i] * g_[i];
      }
    });
    gg = e[0];
    conjugate = false;
    direction_and_step();
  }

  // Step on S; release bound cells whose gap says so: p = 0 with g < 0, p = H with g > 0
  // (README Eq. 8); a release restarts the conjugate directions. While the step is exactly
  // −τ t (nothing clipped, nothing released) the displacement follows as u − τ C t (Eq. 7a).
  void take_step(double tau, bool released) {
    const auto moved = block_reduce<2>(cells.size(), part_, [&](std::size_t lo, std::size_t hi, double* acc) {
      bool clipped = false, freed = false;
      for (const std::size_t i : Slice{cells.data(), lo, hi}) {
        if (set_[i] == kFree) {
          const double step = p[i] - tau * t_[i];
          p[i] = clip(step, hardness);
          clipped = clipped || p[i] != step;
        } else if ((p[i] == 0.0 && g_[i] < 0.0) || (p[i] == hardness && g_[i] > 0.0)) {
          p[i] = clip(p[i] - tau * g_[i], hardness);
          freed = true;
        }
        u_[i] -= tau * r_[i];
      }
      acc[0] = clipped ? 1.0 : 0.0;
      acc[1] = freed ? 1.0 : 0.0;
    });
    released = released || moved[1] > 0.0;
    u_valid = !load && !released && moved[0] == 0.0;
    u_full = false;
    if (load) enforce_load();
    conjugate = !released;
  }

  void iterate() {
    for (;; ++it) {
      bool fresh = false;  // u_ from a product this iteration (not carried by the steps)
      if (!u_valid) {
        u_full = product(p.data(), u_.data());
        fresh = true;
      }
      evaluate();
      if ((res.error < opt.tolerance || it >= opt.max_iterations) && !fresh) {
        // Decide on, and report, the exact gap: one product replaces the carried u_.
        u_full = product(p.data(), u_.data());
        fresh = true;
        evaluate();
      }
      if (res.error < opt.tolerance) {
        res.converged = true;
        break;
      }
      if (it >= opt.max_iterations) break;

      // If S is empty, or the gradient on S vanishes (e.g. an exact warm start whose only defect is
      // cells that must leave a bound), restart with the violating bound cells added to S: t = g
      // there, no conjugation.
      num = 0.0;
      den = 0.0;
      if (free_count > 0) direction_and_step();
      bool released = false;
      if (!(den > 0.0)) {
        released = true;
        release_and_step();
      }
      if (!(den > 0.0)) {
        ++it;  // nothing left to move: stop; reported unconverged since ε ≥ tolerance
        if (!fresh) {
          u_full = product(p.data(), u_.data());
          fresh = true;
          evaluate();
        }
        break;
      }
      const double tau = num / den;
      take_step(tau, released);
    }
  }

  void outputs(double area) {
    res.iterations = it;
    res.approach = w;
    if (!load) {
      // The outputs (plastic volume, the sub-cell edge's open cells) want the exact gap everywhere.
      if (!u_full) op_.apply(p.data(), u_.data());
      for (std::size_t i = 0; i < n; ++i) g_[i] = s[i] - w + u_[i];
    }

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
  }
};

}  // namespace

ContactResult ContactSolver::solve_reference(const std::vector<double>& gap, double approach,
                                             std::vector<double>& pressure, const SolverOptions& options) {
  return run_reference(gap, approach, false, pressure, options);
}

ContactResult ContactSolver::solve_load_reference(const std::vector<double>& gap, double mean_pressure,
                                                  std::vector<double>& pressure, const SolverOptions& options) {
  if (!std::isinf(options.hardness)) throw std::invalid_argument("solve_load: only hardness = +inf is supported");
  if (!(mean_pressure >= 0.0)) throw std::invalid_argument("solve_load: mean pressure must be >= 0");
  return run_reference(gap, mean_pressure, true, pressure, options);
}

ContactResult ContactSolver::run_reference(const std::vector<double>& s, double target, bool load,
                                           std::vector<double>& p, const SolverOptions& opt) {
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

  // Start: clip the warm start into [0, H]; cold start from the coarse grid's solution (Eq. 16)
  // or the best multiple of the rigid interference (one line search), or uniform pressure in load
  // control.
  // Displacement control: only the cells A = {s_i < w} can carry pressure (u = C p ≥ 0, so
  // g_i ≥ s_i − w > 0 elsewhere): the iteration works on A (README Eq. 6a).
  active_.clear();
  if (!load)
    for (std::size_t i = 0; i < n; ++i)
      if (s[i] < w) active_.push_back(static_cast<std::uint32_t>(i));
  bool all_zero = true;
  for (std::size_t i = 0; i < n; ++i) {
    double& v = p[i];
    v = std::isnan(v) || (!load && !(s[i] < w)) ? 0.0 : clip(v, hardness);
    all_zero = all_zero && v == 0.0;
  }
  // The iteration visits the cells of A only (all cells in load control): elsewhere p = 0, t = 0,
  // and g ≥ s − w > 0 needs no u (Eq. 6a); g is formed everywhere once converged.
  ApproachReference ref{s,
                        p,
                        opt,
                        res,
                        w,
                        target,
                        g_ref,
                        hardness,
                        c,
                        load,
                        n,
                        grid.nx,
                        op_,
                        u_,
                        g_,
                        t_,
                        r_,
                        x_,
                        part_,
                        set_,
                        load ? all_ : active_,
                        [this, load](const double* v, double* out) {
                          return load ? (op_.apply(v, out), true) : apply_on(v, active_, out);
                        }};
  if (all_zero && !load && opt.coarse_start && coarse_start(s, w, p, opt, res, true)) all_zero = false;
  if (all_zero) ref.cold_start();
  if (load) ref.enforce_load();

  if (load && all_.size() != n) {
    all_.resize(n);
    for (std::size_t i = 0; i < n; ++i) all_[i] = static_cast<std::uint32_t>(i);
  }
  std::fill(set_.begin(), set_.end(), kOut);
  ref.precondition = !load && opt.precondition;
  ref.gamma = precondition_gamma(active_.size());
  std::fill(t_.begin(), t_.end(), 0.0);
  ref.iterate();
  ref.outputs(area);
  if (opt.compute_stiffness && op_.boundary() == Boundary::Open) frozen_stiffness(p, opt, res, true);
  return res;
}

}  // namespace rollspec::contact
