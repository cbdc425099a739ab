#pragma once
// The rolling solver's tangent against central differences of its residual, at the same trial
// increments from the committed state: the check every consistent-linearisation test makes.
#include <Eigen/Dense>

#include "kernels/rolling/solver.hpp"

namespace rollspec::rolling::test {

struct TangentCheck {
  Eigen::MatrixXd k, k_fd;  // the analytic tangent and its central differences
  double error = 0.0;       // max |K - K_fd| / max |K|
};

// K at increments q (next time t1, step dt) and K_fd by central differences of step h in every
// component of q.
inline TangentCheck tangent_check(Solver& s, const Eigen::VectorXd& q, double t1, double dt, double h) {
  Eigen::VectorXd r;
  Eigen::MatrixXd k;
  s.residual_and_tangent(q, t1, dt, r, &k);
  Eigen::MatrixXd k_fd(k.rows(), k.cols());
  for (long j = 0; j < q.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q, rp, rm;
    qp(j) += h;
    qm(j) -= h;
    s.residual_and_tangent(qp, t1, dt, rp, nullptr);
    s.residual_and_tangent(qm, t1, dt, rm, nullptr);
    k_fd.col(j) = (rp - rm) / (2 * h);
  }
  const double error = (k - k_fd).cwiseAbs().maxCoeff() / k.cwiseAbs().maxCoeff();
  return {k, k_fd, error};
}

}  // namespace rollspec::rolling::test
