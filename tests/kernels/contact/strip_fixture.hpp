#pragma once
// Strips for the blocked-force, path-table and equivalent-roughness tests: a window about a Hertz contact, a longer
// strip to move it along, positions on cell centres, rough strips, and the message a refusal throws.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <omp.h>

#include "hertz_fixture.hpp"
#include "rough_fixture.hpp"
#include "kernels/contact/blocked_force.hpp"
#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/grid.hpp"

namespace rollspec::contact::test {

// Window of half-width `span`·a (odd, ball on the middle cell), strip `extra` columns longer and
// `extra_y` rows wider.
struct StripCase {
  Grid window, strip;
};
inline StripCase strip_case(const Hertz& h, double cells, double span, std::size_t extra, std::size_t extra_y = 0) {
  const Grid window = h.grid(cells, span);
  return {window, Grid{window.nx + extra, window.ny + extra_y, window.dx, window.dy}};
}

// Positions x_k = x_0 + k·step·dx on cell centres (strip nx odd: cell centres at integer multiples of dx).
inline std::vector<double> cell_positions(const Grid& strip, long first_cell, long step_cells, std::size_t count) {
  std::vector<double> x(count);
  for (std::size_t k = 0; k < count; ++k)
    x[k] = static_cast<double>(first_cell + static_cast<long>(k) * step_cells) * strip.dx;
  return x;
}

// blocked_force_at_load of a sphere on c's strip, a fresh solver on its window, on `threads` OpenMP threads
// (the count restored after): the same-bits tests run one search at 1 and at 2 threads.
inline BlockedForcePath at_load_on(int threads, const StripCase& c, const Hertz& h, const std::vector<double>& heights,
                                   const std::vector<double>& x, double load, const SolverOptions& opt,
                                   const BlockedForceOptions& o) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  ContactSolver solver(c.window, h.e_star);
  BlockedForcePath r = blocked_force_at_load(solver, c.strip, heights, h.radius, BallShape::Sphere, x, load, opt, o);
  omp_set_num_threads(before);
  return r;
}

// A rough elastic-plastic strip about the Hertz ball: the window and strip of `strip` (strip_case of a Hertz{}), waves
// of 0.15 times the Hertz approach and `wavelength` contact radii, `count` positions `step` cells apart from cell
// `first`, hardness 0.5 p0. Taken apart by a structured binding: auto& [h, c, heights, x, opt] = strip.
struct RoughStrip {
  Hertz h;
  StripCase c;
  std::vector<double> heights, x;
  SolverOptions opt;
  RoughStrip(const StripCase& strip, double wavelength, long first, long step, std::size_t count)
      : c(strip),
        heights(wavy_heights(c.strip, 0.15 * h.approach, wavelength * h.a())),
        x(cell_positions(c.strip, first, step, count)) {
    opt.hardness = 0.5 * h.p0();
  }
};

// The wavy strip the blocked-force path tests share: 12 cells per contact radius, a window of 1.9 radii, the
// strip 36 x 10 cells larger (by default), waves of 0.4 contact radii, 16 positions two cells apart from cell -15.
struct WavyStrip : RoughStrip {
  // `extra` cells more than the window along the path, `count` positions from cell `first`.
  explicit WavyStrip(std::size_t extra = 36, long first = -15, std::size_t count = 16)
      : RoughStrip(strip_case(Hertz{}, 12.0, 1.9, extra, 10), 0.4, first, 2, count) {}

  // The path at `load` (blocked_force_at_load, a sphere) on `threads` OpenMP threads.
  BlockedForcePath at_load(int threads, double load, const BlockedForceOptions& o) const {
    return at_load_on(threads, c, h, heights, x, load, opt, o);
  }
};

// What f throws as std::invalid_argument ("" when it does not throw).
inline std::string thrown_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace rollspec::contact::test
