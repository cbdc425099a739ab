#include "kernels/rolling/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollspec::rolling {

using Eigen::VectorXd;

NewtonDriver::NewtonDriver(const std::vector<int>& eq, int neq) : eq_(eq), neq_(neq) {
  sink_.eq = &eq_;
  sink_.neq = neq_;
  band_sink_.eq = &eq_;
  band_sink_.lu = &band_;
  rf_.resize(neq_);
  dq_.resize(neq_);
}

bool band_pays(int n, int kl, int ku, long long entries) {
  return static_cast<long long>(n) * (2 * kl + ku + 1) <= 4 * entries;
}

void NewtonDriver::choose_solver(LinearSolver wanted) {
  const Eigen::SparseMatrix<double>& A = sink_.A;
  int kl = 0, ku = 0;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      kl = std::max(kl, static_cast<int>(it.row()) - c);
      ku = std::max(ku, c - static_cast<int>(it.row()));
    }
  banded_ =
      wanted == LinearSolver::Band || (wanted == LinearSolver::Automatic && band_pays(neq_, kl, ku, A.nonZeros()));
  if (!banded_) return;
  // this pass assembled into the sparse matrix: its values (the same sums) seed the band
  band_.resize(neq_, kl, ku);
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      band_.at(static_cast<int>(it.row()), c) = it.value();
}

bool NewtonDriver::solve(const SolverOptions& opt, const Assemble& assemble, VectorXd& q, VectorXd& R, StepReport& rep,
                         const Rewind& rewind) {
  VectorXd& rf = rf_;
  VectorXd& dq = dq_;
  VectorXd& q_acc = q_acc_;
  rep.residual_norms.clear();
  double last = std::numeric_limits<double>::infinity();
  q_acc = q;
  double G0 = 0.0, step = 1.0, best_rn = std::numeric_limits<double>::infinity(), best_step = 1.0;
  int nback = 0, newton = 0;  // newton: Newton directions (line-search trials not counted)
  bool forced = false;
  // Residual and tangent at q into R and the band or the sparse pattern; false: not usable.
  auto assemble_with_tangent = [&]() {
    bool usable = false, mismatch = false, recorded = false;
    if (banded_) {
      band_sink_.begin();
      usable = assemble(q, R, &band_sink_);
      mismatch = band_sink_.mismatch;
    } else {
      recorded = sink_.recording;
      sink_.begin();
      usable = assemble(q, R, &sink_);
      sink_.finish();
      mismatch = sink_.mismatch;
    }
    if (mismatch) {  // pattern changed (should not happen): record it again
      sink_.recording = true;
      banded_ = false;
      sink_.begin();
      usable = assemble(q, R, &sink_);
      sink_.finish();
      recorded = true;
    }
    if (recorded) choose_solver(opt.linear_solver);
    return usable;
  };
  for (int it = 0;; ++it) {
    // Residual only where the iterate is expected to end the iteration (R-44a): from the Newton
    // direction at which the last solve converged on, the tangent is assembled only when the
    // residual asks for another direction (the pairs rewound, the same residual again).
    const bool lazy = rewind && newton > 0 && newton >= expect_;
    const bool usable = lazy ? assemble(q, R, nullptr) : assemble_with_tangent();
    if (!usable) return false;
    for (std::size_t i = 0; i < eq_.size(); ++i)
      if (eq_[i] >= 0) rf(eq_[i]) = R(static_cast<Eigen::Index>(i));
    const double rn = rf.norm();
    rep.residual_norms.push_back(rn);
    rep.iterations = it;
    // Backtracking line search on G(s) = dq . R(q_acc + s dq) (README R-42): a full
    // Newton step that overshoots (|G(1)| > 0.8 |G(0)|, e.g. across a stick/slip kink of the
    // friction law) is halved, up to max_line_search times; if no trial qualifies, the
    // trial with the smallest residual is taken.
    if (newton > 0 && opt.max_line_search > 0 && !forced) {
      const double G = dq.dot(rf);
      const bool bad = !std::isfinite(rn) || std::abs(G) > 0.8 * std::abs(G0);
      if (std::isfinite(rn) && rn < best_rn) {
        best_rn = rn;
        best_step = step;
      }
      if (bad && (nback < opt.max_line_search || best_step != step)) {
        if (nback < opt.max_line_search) {
          ++nback;
          step *= 0.5;
        } else {
          step = best_step;  // exhausted: go back to the best trial and accept it
          forced = true;
        }
        for (std::size_t i = 0; i < eq_.size(); ++i)
          if (eq_[i] >= 0) q(static_cast<Eigen::Index>(i)) = q_acc(static_cast<Eigen::Index>(i)) + step * dq(eq_[i]);
        last = step * dq.lpNorm<Eigen::Infinity>();
        continue;
      }
    }
    forced = false;
    if (!std::isfinite(rn)) return false;
    if (rn <= opt.force_tol || (newton > 0 && last <= opt.disp_tol)) {
      expect_ = newton;
      break;
    }
    if (newton >= opt.max_iterations) return false;
    if (lazy) {  // another direction after all: the tangent at this iterate
      ++lazy_misses_;
      rewind();
      if (!assemble_with_tangent()) return false;
    }
    ++newton;
    if (sink_.new_pattern) {  // once (again only if the pattern ever changes)
      if (!banded_) lu_.analyzePattern(sink_.A);
      sink_.new_pattern = false;
      ++analyses_;
    }
    if (banded_) {
      if (!band_.factorize()) return false;
      dq = -rf;
      band_.solve(dq.data());
    } else {
      lu_.factorize(sink_.A);
      if (lu_.info() != Eigen::Success) return false;
      dq = lu_.solve(-rf);
    }
    G0 = dq.dot(rf);
    q_acc = q;
    step = 1.0;
    nback = 0;
    best_rn = std::numeric_limits<double>::infinity();
    best_step = 1.0;
    for (std::size_t i = 0; i < eq_.size(); ++i)
      if (eq_[i] >= 0) q(static_cast<Eigen::Index>(i)) += dq(eq_[i]);
    last = dq.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(last)) return false;
  }
  return true;
}

}  // namespace rollspec::rolling
