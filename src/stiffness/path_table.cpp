#include "src/stiffness/path_table.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernels/contact/equivalent_roughness.hpp"
#include "kernels/contact/path_table.hpp"
#include "kernels/contact/version.hpp"
#include "kernels/texture/line_texture.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/progress.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/stiffness/study_strip.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/io/number_text.hpp"
#include "src/stiffness/strip_solves.hpp"

namespace rollspec::stiffness {

using namespace study;

const TableKind kPathTableKind = {
    kPathTableFileType, "/path_table", "path-table-", "path table", {"B41..B46", "Polonsky-Keer 1999", "D-6", "D-7"}};

namespace {

constexpr double kPeakSigmas = 7.0;   // the strip's highest point (and deepest valley), in rms heights
constexpr double kReach = 3.0;        // δ_hi = max δ_c + 3 δ_H (B43)
constexpr double kCheckSolves = 6.0;  // contact solves of one cold B47 check (ER-1's Newton, coarse start)

}  // namespace

PathTableGeometry path_table_geometry(const study::PathTableSection& p, const study::BlockedForceSection& bf,
                                      const study::StripSurfaceSection& surface, const texture::Psd& psd, double radius,
                                      double e_star, double load, double path_length) {
  PathTableGeometry g;
  g.ladder = p.ladder == PathLadder::first_contact;
  g.base = blocked_force_geometry(bf, surface, psd, radius, e_star, load, 0.0);
  const double a = g.base.contact_radius, dx = g.base.cell, dh = a * a / radius;
  g.path_length = path_length;
  g.approaches = static_cast<std::size_t>(p.approaches);
  // Derived step: a/2 with B45b's cubic convolution in ξ, a/4 with B45's linear (kernels/beam B45b).
  const double per_radius = p.interpolation == PathInterpolation::cubic ? 2.0 : 4.0;
  g.step = p.step > 0 ? static_cast<std::size_t>(p.step)
                      : std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(a / per_radius / dx + 1e-9)));
  // Window: every cell with rigid interference at δ_hi (BF-5; the build refuses otherwise).
  const double reach =
      std::max(2.6 * a, std::sqrt(2.0 * radius * ((kReach + 0.3) * dh + 2.0 * kPeakSigmas * g.base.rms)));
  g.window = texture::fast_even_length(static_cast<std::size_t>(std::ceil(2.0 * reach / dx - 1e-9)) + 2);
  g.ny = surface.ny_set ? static_cast<std::size_t>(surface.ny) : g.window;
  g.window = std::min(g.window, g.ny);
  if (g.window < 8)
    surface.ny_origin.refuse("leaves a path-table window of " + std::to_string(g.window) +
                             " cells; allowed: 8 or more");
  const double step_length = static_cast<double>(g.step) * dx;
  g.positions = static_cast<std::size_t>(std::ceil(path_length / step_length - 1e-9)) + 2;  // one step beyond the end
  const std::size_t need = g.window + (g.positions - 1) * g.step + 1;
  if (p.strip_length > 0.0) {
    g.nx = static_cast<std::size_t>(std::round(p.strip_length / dx));
    if (g.nx < need)
      p.origin(p.strip_length)
          .refuse("= " + io::exact_text(p.strip_length) + " m is shorter than the ball's path in the run (" +
                  um(path_length) + " plus one step of " + um(step_length) + ") plus the solver window (" +
                  std::to_string(g.window) + " cells of " + um(dx) + "); allowed: 0 (derived) or at least " +
                  io::exact_text(static_cast<double>(need) * dx) + " m");
  } else {
    g.nx = need;
  }
  g.nx += g.nx % 2;
  // Cost: J rows and the two B43a usually adds, over every position, at 3.7e-7 s per solve
  // (contact_box_work, fitted on three textures; bench/contact/bench_tables.py's rig: 13.5 s CPU).
  // B43b: J rows, and about one more where a rough position needs it (8.96 per position for J = 8 on a
  // 50 mm section of the seed 002 rig), each started from the row below and about half as dear
  // (1.95e-7: plane-ladder estimates were 1.76-2.03 x the wall on the rig's and a rougher section at
  // a/4 and a/2, bench/contact/bench_path_positions.py).
  g.solve_seconds = 3.7e-7 * contact_box_work(g.base, g.window, radius);
  // B47's checks: a cold load-controlled solve in every kPathCheckStride-th interval, about kCheckSolves solves.
  g.estimated_seconds = (g.ladder ? 1.95e-7 / 3.7e-7 : 1.0) * g.solve_seconds *
                            static_cast<double>(g.positions * (g.approaches + (g.ladder ? 1 : 2))) +
                        kCheckSolves * g.solve_seconds * static_cast<double>(g.positions / kPathCheckStride);
  const std::size_t chunk = contact::PathTableOptions{}.chunk_positions;
  g.threads = std::max(1, std::min(omp_get_max_threads(), static_cast<int>((g.positions + chunk - 1) / chunk)));
  return g;
}

std::string PathTableGeometry::describe() const {
  std::string buf;
  const double dx = base.cell;
  buf = io::formatted(
      "strip 0 of the surface, cell %s (a/%.3g)%s, strip %zu x %zu cells (%s long, %s wide), window %zu cells, "
      "%zu approaches %s x %zu positions (step %zu cells = %s) over the "
      "ball's path of %s; contact radius a = %s, "
      "texture rms %s; build about %.2g s CPU, %.2g s wall on %d thread%s",
      um(dx).c_str(), base.contact_radius / dx,
      base.truncated_wavelength > 0.0 ? (", texture below " + um(base.truncated_wavelength) + " dropped").c_str() : "",
      nx, ny, um(static_cast<double>(nx) * dx).c_str(), um(static_cast<double>(ny) * dx).c_str(), window, approaches,
      ladder ? "above each position's first contact (more there until P >= 5 W, B43b)"
             : "(more until P >= 5 W at every position, B43a)",
      positions, step, um(static_cast<double>(step) * dx).c_str(), um(path_length).c_str(),
      um(base.contact_radius).c_str(), um(base.rms).c_str(), estimated_seconds, estimated_seconds / threads, threads,
      threads == 1 ? "" : "s");
  return buf;
}

namespace {

std::vector<const std::vector<double>*> columns(const PathTableData& t) {
  std::vector<const std::vector<double>*> c{&t.position, &t.approach, &t.first_contact, &t.force};
  if (!t.rows.empty()) c.push_back(&t.rows);
  if (!t.check_position.empty()) c.insert(c.end(), {&t.check_position, &t.check_approach});
  return c;
}

// B47: the strip cells of the checks, midway (to the cell below) in every kPathCheckStride-th interval,
// the first half a stride in; none where the step is one cell (no cell lies between positions).
std::vector<std::size_t> check_cells(const PathTableGeometry& g) {
  std::vector<std::size_t> cells;
  if (g.step < 2) return cells;
  for (std::size_t i = kPathCheckStride / 2; i + 1 < g.positions; i += kPathCheckStride)
    cells.push_back(g.window / 2 + i * g.step + g.step / 2);
  return cells;
}

std::string inputs_text(const TableStudy& ts, const PathTableGeometry& g, double radius, double e_star, double load) {
  std::ostringstream in;
  in << ball_inputs_text(ts, radius, e_star, load) << "\n\n[path_table]\nstrip_cells = " << g.nx
     << "\nwindow = " << g.window << "\nstep = " << g.step << "\npositions = " << g.positions
     << "\napproaches = " << g.approaches << (g.ladder ? "\nladder = first contact (B43b)" : "")
     << "\nreach = " << io::exact_text(kReach)
     << "\ntop_force = " << io::exact_text(contact::PathTableOptions{}.top_force) << "\nmax_approaches = "
     << contact::PathTableOptions{}.max_approaches
     // PT-1: the starts and the chunks of positions set the last bits of the table's values.
     << "\nstart = approach below, extrapolated (PT-1)\nchunk_positions = "
     << contact::PathTableOptions{}.chunk_positions << "\n"
     << "checks = delta_W by a cold load-controlled solve midway in every " << kPathCheckStride
     << "th interval (B47)\n";
  in << strip_inputs_text(ts, StripGrid{g.nx, g.ny, g.base.cell, g.base.derived_cell});
  return in.str();
}

// B47: δ_W at the check cells by ER-1's load-controlled solve, each cold (a chunk of one position), on the
// table's window and strip: what the interpolated table's static approach is compared with.
void check_static_approach(const TableStudy& ts, const PathTableGeometry& g, const contact::Grid& strip_grid,
                           const contact::Grid& window_grid, const std::vector<double>& heights, double radius,
                           double e_star, double load, double first_position, bool quiet, PathTableData& d) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> x;
  for (std::size_t cell : check_cells(g)) x.push_back(strip_grid.x(cell));
  if (x.empty()) return;
  const contact::SolverOptions opts = ts.stiffness.solver;
  contact::EquivalentRoughnessOptions eo;
  eo.chunk_positions = 1;
  eo.stiffness_every = 0;
  eo.load_tolerance = strip_load_tolerance(opts);
  contact::ContactSolver solver(window_grid, e_star);
  contact::EquivalentRoughness r;
  try {
    r = contact::equivalent_roughness(solver, strip_grid, heights, radius, ts.stiffness.shape, x, load, opts, eo);
  } catch (const std::invalid_argument& e) {
    ts.surface.ny_origin.refuse(std::string(e.what()) + "; widen the strip ([surface] ny)");
  }
  require_converged(r.converged, r.max_error, "path table: a check's load-controlled solve");
  for (double xi : x) d.check_position.push_back(xi - first_position);
  d.check_approach = r.approach;
  if (!quiet)
    std::fprintf(stderr, "%spath table: %zu checks (B47), %d CG iterations, %.3g s wall\n",
                 ensemble::rank_prefix().c_str(), x.size(), r.iterations,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

std::string PathTableData::checksum() const {
  std::uint64_t h = column_hash(columns(*this));
  h = io::fnv1a64(&load, sizeof load, h);
  return io::hex16(h);
}

void PathTableData::load_from(const io::Hdf5Reader& r) {
  position = r.read("/path_table/position");
  approach = r.read("/path_table/approach");
  first_contact = r.read("/path_table/first_contact");
  force = r.read("/path_table/force");
  rows = r.exists("/path_table/rows") ? r.read("/path_table/rows") : std::vector<double>{};
  check_position =
      r.exists("/path_table/check_position") ? r.read("/path_table/check_position") : std::vector<double>{};
  check_approach =
      r.exists("/path_table/check_approach") ? r.read("/path_table/check_approach") : std::vector<double>{};
  load = r.double_attribute("/path_table", "load");
}

void PathTableData::save_to(io::Hdf5Writer& w) const {
  w.write("/path_table/position", {position.size()}, position.data(), "m",
          "ball position xi_k along the path, from the traverse's start");
  w.write("/path_table/approach", {approach.size()}, approach.data(), "m",
          rows.empty() ? "rigid approach delta_j from the strip's mean plane (kernels/beam B43)"
                       : "offset s_j of the rigid approach above the first contact delta_c(xi_k) (kernels/beam B43b)");
  if (!rows.empty())
    w.write("/path_table/rows", {rows.size()}, rows.data(), "1",
            "rows solved at each position (kernels/beam B43b): up to the first carrying 5 W there");
  w.write("/path_table/first_contact", {first_contact.size()}, first_contact.data(), "m",
          "first-contact approach delta_c(xi_k) (kernels/beam B42)");
  w.write("/path_table/force", {approach.size(), position.size()}, force.data(), "N",
          rows.empty()
              ? "P(delta_j, xi_k): force of the elastic-plastic half-space solve (kernels/beam B41), approach x "
                "position"
              : "P(delta_c(xi_k) + s_j, xi_k): force of the elastic-plastic half-space solve (kernels/beam "
                "B41, B43b), approach x position; NaN above the rows solved at that position");
  if (!check_position.empty()) {
    w.write("/path_table/check_position", {check_position.size()}, check_position.data(), "m",
            "B47: check positions xi, midway between table positions in every 16th interval");
    w.write("/path_table/check_approach", {check_approach.size()}, check_approach.data(), "m",
            "B47: approach delta_W carrying the load there by a cold load-controlled solve, from the mean plane");
  }
  w.attribute("/path_table", "load", load);
}

CachedTable path_cached_table(const TableStudy& ts, const PathTableGeometry& g, double radius, double e_star,
                              double load) {
  return CachedTable(kPathTableKind, ts.store, inputs_text(ts, g, radius, e_star, load));
}

PathTableData build_path_table(const TableStudy& ts, const PathTableGeometry& g, double radius, double e_star,
                               double load, bool quiet) {
  const double dx = g.base.cell;
  const texture::Surface strip = study_strip(ts, StripGrid{g.nx, g.ny, dx, g.base.derived_cell}, 0);
  const contact::Grid strip_grid{g.nx, g.ny, dx, dx}, window_grid{g.window, g.window, dx, dx};
  std::vector<double> positions;
  for (std::size_t k = 0; k < g.positions; ++k) positions.push_back(strip_grid.x(g.window / 2 + k * g.step));
  contact::SolverOptions opts = ts.stiffness.solver;
  const contact::BallShape shape = ts.stiffness.shape;
  contact::PathTableOptions po;
  po.approaches = g.approaches;
  po.reach = kReach;
  if (g.ladder) po.ladder = contact::PathLadder::FirstContact;
  if (!quiet) std::fprintf(stderr, "%spath table: %s\n", ensemble::rank_prefix().c_str(), g.describe().c_str());
  const auto start = std::chrono::steady_clock::now();
  // Bar over the solves of the J rows and the two B43a usually adds (not past its total); one line
  // per pass of rows over the path.
  const std::size_t expected = g.positions * (g.approaches + (g.ladder ? 1 : 2));
  ensemble::Progress progress("path table solves", expected, quiet);
  progress.show_after(2.0);
  std::size_t solves_done = 0;
  long pass_solves = 0, pass_iterations = 0;
  if (!quiet)
    po.on_chunk = [&](std::size_t rows, std::size_t positions_done, int solves, int iterations) {
      const std::size_t n = std::min(static_cast<std::size_t>(solves), expected - std::min(expected, solves_done));
      solves_done += static_cast<std::size_t>(solves);
      if (n > 0) progress.advance(n);
      pass_solves += solves;
      pass_iterations += iterations;
      if (positions_done < g.positions) return;
      std::fprintf(stderr, "%spath table: %zu rows over %zu positions done, %.1f CG iterations per solve, %.3g s\n",
                   ensemble::rank_prefix().c_str(), rows, positions_done,
                   static_cast<double>(pass_iterations) / static_cast<double>(std::max(1L, pass_solves)),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      pass_solves = pass_iterations = 0;
    };
  contact::PathTable t;
  try {
    t = contact::build_path_table(window_grid, e_star, strip_grid, strip.heights, radius, shape, positions, load, opts,
                                  po);
  } catch (const std::invalid_argument& e) {
    ts.surface.ny_origin.refuse(std::string(e.what()) + "; widen the strip ([surface] ny)");
  }
  progress.finish();  // the bar's "took" line (a log's only line of it), short of its total when B43a adds less
  require_converged(t.converged, t.max_error, "path table: a contact solve");
  if (!quiet)
    std::fprintf(
        stderr,
        "%spath table: %zu approaches (last carries >= %.3g W everywhere), %d solves, %d CG iterations, %.3g s wall\n",
        ensemble::rank_prefix().c_str(), t.approach.size(), t.top_force, t.solves, t.iterations,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  PathTableData d;
  check_static_approach(ts, g, strip_grid, window_grid, strip.heights, radius, e_star, load, positions.front(), quiet,
                        d);
  d.position = from_first(t.position);
  d.approach = t.approach;
  d.first_contact = t.first_contact;
  d.force = t.force;
  if (t.ladder == contact::PathLadder::FirstContact) d.rows.assign(t.rows.begin(), t.rows.end());
  d.load = load;
  return d;
}

}  // namespace rollspec::stiffness
