// Newton-Raphson iteration of one step of the rolling Solver (README Sec. 6, R-40, R-42): sparse
// assembly into a fixed pattern (analysed once, again only if it ever changes), SparseLU
// factorisation per iteration, optional backtracking line search; imposed DOFs eliminated.
// Only the iteration: the caller commits the converged increments. Internal to kernels/rolling.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <functional>
#include <vector>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/solver.hpp"

namespace rollspec::rolling {

class NewtonDriver {
 public:
  // eq: global DOF -> free equation (-1: imposed), neq free equations; eq must outlive the driver.
  NewtonDriver(const std::vector<int>& eq, int neq);

  // Assembles the residual (all DOFs) at q and the tangent into K; false: the iterate cannot be
  // used (a closest point not found), the step is to be cut.
  using Assemble = std::function<bool(const Eigen::VectorXd& q, Eigen::VectorXd& R, Sink* K)>;

  // Iterates the free entries of q (imposed entries as given) until ||R_free||_2 <= force_tol or
  // the last correction ||dq||_inf <= disp_tol. Returns false when it does not converge within
  // max_iterations Newton directions, meets a non-finite value or a failed factorisation. R holds
  // the residual at the returned q (imposed entries: the reactions); rep gets the iteration count
  // and the residual norms.
  bool solve(const SolverOptions& options, const Assemble& assemble, Eigen::VectorXd& q, Eigen::VectorXd& R,
             StepReport& rep);

  int pattern_analyses() const { return analyses_; }

 private:
  const std::vector<int>& eq_;
  int neq_ = 0;
  SparseSink sink_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  int analyses_ = 0;  // SparseLU::analyzePattern calls
};

}  // namespace rollspec::rolling
