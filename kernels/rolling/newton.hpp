// Newton-Raphson iteration of one step of the rolling Solver (README Sec. 6, R-40, R-42, R-44):
// the first assembly records the sparse pattern; from it the driver chooses a band LU (assembly
// straight into its band) or SparseLU (pattern analysed once, again only if it ever changes),
// factorised per iteration; optional backtracking line search; imposed DOFs eliminated.
// Only the iteration: the caller commits the converged increments. Internal to kernels/rolling.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <functional>
#include <vector>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/band_lu.hpp"
#include "kernels/rolling/solver.hpp"

namespace rollspec::rolling {

class NewtonDriver {
 public:
  // eq: global DOF -> free equation (-1: imposed), neq free equations; eq must outlive the driver.
  NewtonDriver(const std::vector<int>& eq, int neq);

  // Assembles the residual (all DOFs) at q and the tangent into K; false: the iterate cannot be
  // used (a closest point not found), the step is to be cut.
  using Assemble = std::function<bool(const Eigen::VectorXd& q, Eigen::VectorXd& R, Sink* K)>;
  // Undoes the side effects of the last assemble (contact search starts), so that assembling the
  // same q again gives the same bits.
  using Rewind = std::function<void()>;

  // Iterates the free entries of q (imposed entries as given) until ||R_free||_2 <= force_tol or
  // the last correction ||dq||_inf <= disp_tol. Returns false when it does not converge within
  // max_iterations Newton directions, meets a non-finite value or a failed factorisation. R holds
  // the residual at the returned q (imposed entries: the reactions); rep gets the iteration count
  // and the residual norms. With rewind (R-44a), iterates from the Newton direction at which the
  // last solve converged on are assembled without the tangent first (K = nullptr), and again with
  // it (after rewind) only when the residual asks for another direction: the same iterates, bits
  // and counts as assembling the tangent every time, one tangent fewer per converged step.
  bool solve(const SolverOptions& options, const Assemble& assemble, Eigen::VectorXd& q, Eigen::VectorXd& R,
             StepReport& rep, const Rewind& rewind = nullptr);

  // Analyses of a new pattern before a factorisation (SparseLU::analyzePattern, or the band set up).
  int pattern_analyses() const { return analyses_; }
  // Residual-only passes that had to be repeated with the tangent (R-44a).
  long lazy_misses() const { return lazy_misses_; }
  // The linear solver in use after the first iteration (Band or Sparse).
  LinearSolver linear_solver() const { return banded_ ? LinearSolver::Band : LinearSolver::Sparse; }

 private:
  const std::vector<int>& eq_;
  int neq_ = 0;
  SparseSink sink_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  int analyses_ = 0;
  BandLU band_;
  BandSink band_sink_;
  bool banded_ = false;
  int expect_ = 1 << 30;  // Newton directions the last converged solve took (none yet: never lazy)
  long lazy_misses_ = 0;
  Eigen::VectorXd rf_, dq_, q_acc_;  // sized once, reused by every step

  // After a recording pass: band or sparse for the new pattern.
  void choose_solver(LinearSolver wanted);
};

// the band when its storage n (2 kl + ku + 1) is at most 4 times the pattern's entries
// (a beam numbered along its length: about 2.4), else the sparse LU.
bool band_pays(int n, int kl, int ku, long long entries);

}  // namespace rollspec::rolling
