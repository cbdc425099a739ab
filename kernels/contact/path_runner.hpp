#pragma once
// internal: one path of the blocked force at a given approach on the moving solver window (BF-1, BF-2,
// BF-5, BF-6, BF-6', BF-6c), shared by the load search (BF-3, BF-4') and the checks (BF-9) in
// blocked_force.cpp.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

#include "kernels/contact/blocked_force.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/path_window.hpp"

namespace rollspec::contact::detail {

// Converged fields of one path (window arrays) and their rates dp/dd, for the next load-search path.
struct PathFields {
  double approach = 0.0;
  std::vector<std::vector<double>> pressure, rate;
};

// Validated path set-up (PathWindow: window placement, BF-5, BF-6) and one path at a given approach.
class PathRunner {
 public:
  PathRunner(ContactSolver& solver, const Grid& strip, const std::vector<double>& heights, double radius,
             BallShape shape, const std::vector<double>& positions, const BlockedForceOptions& path_options)
      : solver_(solver),
        window_(checked_window(solver), strip, heights, radius, shape, positions, path_options.centre_y,
                "blocked_force"),
        positions_(positions),
        popt_(path_options) {}

  double max_approach(std::size_t* position) const { return window_.max_approach(position); }
  std::size_t positions() const { return positions_.size(); }
  // ε (README Eq. 9) of each solve of the last path run.
  const std::vector<double>& solve_error() const { return solve_error_; }
  [[noreturn]] void reject(std::size_t k, double d, const char* prefix = "") const { window_.reject(k, d, prefix); }
  // Keep only every stride-th position's field and rate (BF-9's check positions); 1: each of the first store_count.
  void set_store_stride(std::size_t stride) { store_stride_ = std::max<std::size_t>(1, stride); }

  // One path at approach d (BF-2). `previous` (optional): the fields of an earlier path, used as
  // starts for its positions (BF-6'); `store` (optional) receives the first
  // `store_count` fields of this path and their frozen-set rates dp/dd.
  BlockedForcePath run(double d, const SolverOptions& opt, const PathFields* previous, PathFields* store,
                       std::size_t store_count);

 private:
  static const Grid& checked_window(ContactSolver& solver) {
    if (solver.half_space().boundary() != Boundary::Open)
      throw std::invalid_argument("blocked_force: the solver must use the open boundary");
    return solver.grid();
  }

  ContactSolver& solver_;
  std::vector<std::unique_ptr<ContactSolver>> extra_;  // the other threads' solvers (chunks)
  PathWindow window_;
  std::vector<double> positions_;
  BlockedForceOptions popt_;
  std::vector<double> solve_error_;
  std::size_t store_stride_ = 1;
};

// Adds a path's counts (paths, solves, iterations) to a running total.
void accumulate(BlockedForcePath& total, const BlockedForcePath& path);

}  // namespace rollspec::contact::detail
