#include "src/stiffness/strip_equivalent_roughness.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "kernels/contact/equivalent_roughness.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"
#include "src/stiffness/study_strip.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/io/number_text.hpp"
#include "src/stiffness/strip_solves.hpp"

namespace rollspec::stiffness {

using namespace study;

namespace {

// As the synthesised stage: fixed chunks, the same bits for any thread count.
constexpr std::size_t kChunkPositions = 64;
// Solves per position of the Newton on the approach (ER-1), as equivalent_roughness_table.
constexpr double kSolvesPerPosition = 4.0;
// Welch segment of the strip's h_eq PSD (positions), at most.
constexpr std::size_t kSegment = 256;

std::string inputs_text(const TableStudy& ts, const PathTableGeometry& g, double radius, double e_star, double load) {
  std::ostringstream in;
  in << ball_inputs_text(ts, radius, e_star, load) << "\n\n[equivalent_roughness]\nline = strip\nstrip_cells = " << g.nx
     << "\nwindow = " << g.window << "\nstep = " << g.step << "\npositions = " << g.positions
     << "\nchunk_positions = " << kChunkPositions << "\nsegment = " << kSegment
     << "\noutputs = h_eq, k_eq\nload_tolerance = " << io::exact_text(strip_load_tolerance(ts.stiffness.solver))
     << "\n";
  in << strip_inputs_text(ts, StripGrid{g.nx, g.ny, g.base.cell, g.base.derived_cell});
  return in.str();
}

double estimated_seconds(const PathTableGeometry& g) {
  // The path table's per-solve cost (path_table_geometry), kSolvesPerPosition solves per position.
  return g.solve_seconds * static_cast<double>(g.positions) * kSolvesPerPosition;
}

}  // namespace

std::string strip_equivalent_roughness_describe(const PathTableGeometry& g) {
  std::string buf;
  const double dx = g.base.cell;
  buf = io::formatted(
      "line = strip: h_eq of strip 0 of the surface along the ball's path of %s, the path table's grid: cell %s "
      "(a/%.3g), strip %zu x %zu cells, window %zu cells, %zu positions (step %zu cells = %s); build about "
      "%.2g s on one core; every realisation rolls over this one strip (K > 1 repeats the same run)",
      um(g.path_length).c_str(), um(dx).c_str(), g.base.contact_radius / dx, g.nx, g.ny, g.window, g.positions, g.step,
      um(static_cast<double>(g.step) * dx).c_str(), estimated_seconds(g));
  return buf;
}

CachedTable strip_equivalent_roughness_cached_table(const TableStudy& ts, const PathTableGeometry& g, double radius,
                                                    double e_star, double load) {
  return CachedTable(kEquivalentRoughnessTableKind, ts.store, inputs_text(ts, g, radius, e_star, load));
}

EquivalentRoughnessTable build_strip_equivalent_roughness(const TableStudy& ts, const PathTableGeometry& g,
                                                          double radius, double e_star, double load, bool quiet) {
  const double dx = g.base.cell;
  // The strip and positions of build_path_table: the same heights under the same ball centres.
  const texture::Surface strip = study_strip(ts, StripGrid{g.nx, g.ny, dx, g.base.derived_cell}, 0);
  const contact::Grid strip_grid{g.nx, g.ny, dx, dx}, window_grid{g.window, g.window, dx, dx};
  std::vector<double> positions;
  for (std::size_t k = 0; k < g.positions; ++k) positions.push_back(strip_grid.x(g.window / 2 + k * g.step));
  const contact::SolverOptions opts = ts.stiffness.solver;
  contact::EquivalentRoughnessOptions po;
  po.chunk_positions = kChunkPositions;
  po.load_tolerance = strip_load_tolerance(opts);
  if (!quiet)
    std::fprintf(stderr, "%sequivalent roughness: %s\n", ensemble::rank_prefix().c_str(),
                 strip_equivalent_roughness_describe(g).c_str());
  const auto start = std::chrono::steady_clock::now();
  contact::ContactSolver solver(window_grid, e_star);
  contact::EquivalentRoughness r;
  try {
    r = contact::equivalent_roughness(solver, strip_grid, strip.heights, radius, ts.stiffness.shape, positions, load,
                                      opts, po);
  } catch (const std::invalid_argument& e) {
    ts.surface.ny_origin.refuse(std::string(e.what()) + "; widen the strip ([surface] ny)");
  }
  require_converged(r.converged, r.max_error, "equivalent roughness: strip 0");
  if (!quiet)
    std::fprintf(stderr, "%sequivalent roughness: strip 0, %d CG iterations, %.3g s wall\n",
                 ensemble::rank_prefix().c_str(), r.iterations,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EquivalentRoughnessTable t;
  t.position = from_first(r.position);
  t.height = r.height;
  t.stiffness = r.stiffness;
  t.smooth_approach = r.smooth_approach;
  t.smooth_stiffness = r.smooth_stiffness;
  t.load = load;
  t.strips = 1.0;
  // The strip's own h_eq PSD (per rad/m, D-5), for /roughness and the log.
  spectral::WelchConfig wc;
  wc.sample_rate = 1.0 / (static_cast<double>(g.step) * dx);
  wc.segment = std::min(kSegment, positions.size() - positions.size() % 2);
  wc.overlap = wc.segment / 2;
  const spectral::WelchPlan plan(wc);
  spectral::WelchWorkspace ws(wc.segment);
  std::vector<double> one(plan.n_freq());
  plan.psd(r.height.data(), r.height.size(), one.data(), ws);
  for (std::size_t k = 0; k < one.size(); ++k) {
    t.psd_wavenumber.push_back(2.0 * M_PI * plan.frequency_step() * static_cast<double>(k));
    t.psd.push_back(one[k] / (2.0 * M_PI));
  }
  return t;
}

}  // namespace rollspec::stiffness
