#pragma once
// Settings of the rolling runs the tests (and bench/rolling/bench_rolling_impacts.cpp) make: the steps and records of
// a run, and the Newton settings of seed 000 example 4.4 (flying beam). Header-only.
#include "kernels/rolling/solver.hpp"

namespace rollspec::rolling::test {

// Steps of dt to t_end, a record every `record_every` steps (energies included).
inline RunOptions run_options(double dt, double t_end, int record_every = 1) {
  RunOptions ro;
  ro.dt = dt;
  ro.t_end = t_end;
  ro.record_every = record_every;
  return ro;
}

// Example 4.4 (flying beam): residual to 1e-6, up to 8 line-search halvings and 40 Newton iterations a step.
inline SolverOptions flying_beam_options() {
  SolverOptions o;
  o.force_tol = 1e-6;
  o.max_line_search = 8;
  o.max_iterations = 40;
  return o;
}

}  // namespace rollspec::rolling::test
