#include "src/stiffness/equivalent_roughness_table.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernels/contact/equivalent_roughness.hpp"
#include "kernels/contact/version.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/progress.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/stiffness/study_strip.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/io/number_text.hpp"
#include "src/stiffness/strip_solves.hpp"

namespace rollspec::stiffness {

using namespace study;

namespace {

// Positions per warm-started chunk: fixed, so the table has the same bits for any thread count
// (EquivalentRoughnessOptions::chunk_positions).
constexpr std::size_t kChunkPositions = 64;
// ER-8: every 16th position checked at the full tolerance (BF-9's stride).
constexpr std::size_t kCheckStride = 16;
// CPU seconds per position: one load-controlled solve (contact README Eq. 17) on a 144^2 window, scaled
// to other windows as the padded FFT product, N log2 N with N = 4 window^2. The window cannot see how
// far a texture's listed cells reach, so on three textures (bench/contact/bench_plan_estimates.py: the
// seed 002 rig, the Ra 0.3 um finish, a smoother one; geometric means of two sessions' one-thread
// builds) one constant's estimates spread over a factor 2. The constant centres that spread;
// plan measures its first solves instead (probe_equivalent_roughness).
constexpr double kSecondsPerPosition144 = 28e-3;

std::vector<const std::vector<double>*> columns(const EquivalentRoughnessTable& t) {
  return {&t.position, &t.height, &t.psd_wavenumber, &t.psd, &t.stiffness};
}

std::string inputs_text(const TableStudy& ts, const BlockedForceGeometry& g, double radius, double e_star,
                        double load) {
  std::ostringstream in;
  in << ball_inputs_text(ts, radius, e_star, load)
     << "\n\n[equivalent_roughness]\nstrips = " << ts.equivalent_roughness.strips << "\nstrip_cells = " << g.nx
     << "\nwindow = " << g.window << "\nstep = " << g.step << "\nsegment = " << g.segment
     << "\nchunk_positions = " << kChunkPositions << "\nsolve = load control\noutputs = h_eq, k_eq\nload_tolerance = "
     << io::exact_text(strip_load_tolerance(ts.stiffness.solver)) << "\n";
  // ER-8 enters only when set: the reference table's hash is unchanged.
  if (ts.equivalent_roughness.answer_tolerance > 0.0)
    in << "answer_tolerance = " << io::exact_text(ts.equivalent_roughness.answer_tolerance)
       << "\ncheck_stride = " << kCheckStride << "\n";
  in << strip_inputs_text(ts, StripGrid{g.nx, g.ny, g.cell, g.derived_cell});
  return in.str();
}

}  // namespace

const TableKind kEquivalentRoughnessTableKind = {kEquivalentRoughnessFileType,
                                                 "/equivalent_roughness",
                                                 "equivalent-roughness-",
                                                 "equivalent-roughness table",
                                                 {"ER-1..ER-7", "Polonsky-Keer 1999", "D-6", "D-7"}};

std::string EquivalentRoughnessTable::checksum() const {
  std::uint64_t h = column_hash(columns(*this));
  for (double v : {smooth_approach, smooth_stiffness, load, strips}) h = io::fnv1a64(&v, sizeof v, h);
  if (!check_position.empty()) {  // ER-8 only: the reference table's checksum is unchanged
    h = column_hash({&check_position, &check_residual}, h);
    h = io::fnv1a64(&answer_tolerance, sizeof answer_tolerance, h);
  }
  return io::hex16(h);
}

double EquivalentRoughnessTable::stiffness_ratio() const {
  double sum = 0.0;
  std::size_t n = 0;
  for (double k : stiffness)
    if (std::isfinite(k)) {  // the sampled positions (EquivalentRoughnessOptions::stiffness_every)
      sum += k;
      ++n;
    }
  return n == 0 || !(smooth_stiffness > 0.0) ? 1.0 : sum / static_cast<double>(n) / smooth_stiffness;
}

double EquivalentRoughnessTable::psd_at(double k) const { return path_psd_at(psd_wavenumber, psd, k); }

double EquivalentRoughnessTable::band_error_db(double lower, double upper, std::size_t first_bin) const {
  if (position.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  // The PSD is the mean over the strips: the samples behind it are every strip's.
  const auto samples = static_cast<std::size_t>(strips) * position.size();
  return checked_band_error_db(check_residual, position[1] - position[0], samples, psd_wavenumber, psd, lower, upper,
                               first_bin);
}

double equivalent_roughness_seconds(const TableStudy& ts, const BlockedForceGeometry& g) {
  const double n2 = 4.0 * static_cast<double>(g.window) * static_cast<double>(g.window), n144 = 4.0 * 144.0 * 144.0;
  const double per_position = kSecondsPerPosition144 * n2 * std::log2(n2) / (n144 * std::log2(n144));
  return static_cast<double>(ts.equivalent_roughness.strips) * static_cast<double>(g.positions) * per_position;
}

double equivalent_roughness_probe_seconds(const TableStudy& ts, const BlockedForceGeometry& g) {
  if (ts.equivalent_roughness.strips <= 0 || g.positions == 0) return 0.0;
  const std::size_t count = std::min(g.positions, kChunkPositions);
  return equivalent_roughness_seconds(ts, g) * static_cast<double>(count) /
         (static_cast<double>(ts.equivalent_roughness.strips) * static_cast<double>(g.positions));
}

namespace {
// The chunks of kChunkPositions positions share the threads.
int build_threads(const BlockedForceGeometry& g) {
  const int chunks = static_cast<int>((g.positions + kChunkPositions - 1) / kChunkPositions);
  return std::max(1, std::min(omp_get_max_threads(), chunks));
}
}  // namespace

std::string equivalent_roughness_describe(const TableStudy& ts, const BlockedForceGeometry& g) {
  const int threads = build_threads(g);
  const std::string buf = io::formatted(
      "%lld strips (surface realisations 0..%lld) of %zu x %zu cells (%s long, %s wide), cell %s (a/%.3g)%s, "
      "window %zu cells, %zu positions per strip (step %zu cells = %s), Welch segment %zu; contact radius "
      "a = %s; build about %.2g s CPU, %.2g s wall on %d thread%s (from the window; plan%s times its first solves)",
      static_cast<long long>(ts.equivalent_roughness.strips),
      static_cast<long long>(ts.equivalent_roughness.strips - 1), g.nx, g.ny,
      um(static_cast<double>(g.nx) * g.cell).c_str(), um(static_cast<double>(g.ny) * g.cell).c_str(),
      um(g.cell).c_str(), g.contact_radius / g.cell,
      g.truncated_wavelength > 0.0 ? (", texture below " + um(g.truncated_wavelength) + " dropped").c_str() : "",
      g.window, g.positions, g.step, um(static_cast<double>(g.step) * g.cell).c_str(), g.segment,
      um(g.contact_radius).c_str(), equivalent_roughness_seconds(ts, g), equivalent_roughness_seconds(ts, g) / threads,
      threads, threads == 1 ? "" : "s",
      equivalent_roughness_probe_seconds(ts, g) <= kQuickProbeSeconds ? "" : " --probe");
  return buf;
}

void EquivalentRoughnessTable::load_from(const io::Hdf5Reader& r) {
  position = r.read("/equivalent_roughness/position");
  height = r.read("/equivalent_roughness/height");
  psd_wavenumber = r.read("/equivalent_roughness/psd_wavenumber");
  psd = r.read("/equivalent_roughness/psd");
  stiffness = r.read("/equivalent_roughness/stiffness");
  smooth_approach = r.double_attribute("/equivalent_roughness", "smooth_approach");
  smooth_stiffness = r.double_attribute("/equivalent_roughness", "smooth_stiffness");
  load = r.double_attribute("/equivalent_roughness", "load");
  strips = r.double_attribute("/equivalent_roughness", "strips");
  if (r.exists("/equivalent_roughness/check_position")) {
    check_position = r.read("/equivalent_roughness/check_position");
    check_residual = r.read("/equivalent_roughness/check_residual");
    answer_tolerance = r.double_attribute("/equivalent_roughness", "answer_tolerance");
  }
}

void EquivalentRoughnessTable::save_to(io::Hdf5Writer& w) const {
  const auto n_strips = static_cast<std::size_t>(strips);
  w.write("/equivalent_roughness/position", {position.size()}, position.data(), "m", "ball position along the strip");
  w.write("/equivalent_roughness/height", {n_strips, position.size()}, height.data(), "m",
          "equivalent roughness h_eq = delta_smooth - delta_eq at the ball's weight (contact README ER-1, ER-2), strip "
          "x position");
  w.write("/equivalent_roughness/psd_wavenumber", {psd_wavenumber.size()}, psd_wavenumber.data(), "rad/m",
          "wavenumber");
  w.write("/equivalent_roughness/psd", {psd.size()}, psd.data(), "m^3",
          "one-sided PSD of h_eq along the path (Welch per strip, mean over strips)");
  w.write("/equivalent_roughness/stiffness", {n_strips, position.size()}, stiffness.data(), "N/m",
          "contact stiffness k_eq = dP/d delta at delta_eq (contact README ER-7) at every 16th position (NaN between), "
          "strip x position");
  w.attribute("/equivalent_roughness", "smooth_approach", smooth_approach);
  w.attribute("/equivalent_roughness", "smooth_stiffness", smooth_stiffness);
  w.attribute("/equivalent_roughness", "load", load);
  w.attribute("/equivalent_roughness", "strips", strips);
  if (!check_position.empty()) {
    w.write("/equivalent_roughness/check_position", {check_position.size()}, check_position.data(), "m",
            "positions solved again to the full tolerance (contact README ER-8), every strip's in strip order");
    w.write("/equivalent_roughness/check_residual", {check_residual.size()}, check_residual.data(), "m",
            "h_eq of the full-tolerance solve minus the tabulated h_eq there (ER-8)");
    w.attribute("/equivalent_roughness", "answer_tolerance", answer_tolerance);
  }
}

CachedTable equivalent_roughness_cached_table(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                              double e_star, double load) {
  return CachedTable(kEquivalentRoughnessTableKind, ts.store, inputs_text(ts, g, radius, e_star, load));
}

namespace {
// The one-sided PSD of h_eq along the path per rad/m, the mean over t's strips:
// Welch with f_s = 1 / (step dx) cycles/m per strip, the strips' mean in strip order, then per rad/m
// (as the blocked-force F0 PSD; D-5).
void strip_mean_psd(EquivalentRoughnessTable& t, const BlockedForceGeometry& g) {
  const auto n_strips = static_cast<std::size_t>(t.strips), n = t.position.size();
  spectral::WelchConfig wc;
  wc.sample_rate = 1.0 / (static_cast<double>(g.step) * g.cell);
  wc.segment = std::min(g.segment, n);
  wc.overlap = wc.segment / 2;
  const spectral::WelchPlan plan(wc);
  spectral::WelchWorkspace ws(wc.segment);
  std::vector<double> one(plan.n_freq()), mean(plan.n_freq(), 0.0);
  for (std::size_t si = 0; si < n_strips; ++si) {
    plan.psd(t.height.data() + si * n, n, one.data(), ws);
    for (std::size_t k = 0; k < one.size(); ++k) mean[k] += one[k] / static_cast<double>(n_strips);
  }
  t.psd_wavenumber.clear();
  t.psd.clear();
  for (std::size_t k = 0; k < mean.size(); ++k) {
    t.psd_wavenumber.push_back(2.0 * M_PI * plan.frequency_step() * static_cast<double>(k));
    t.psd.push_back(mean[k] / (2.0 * M_PI));
  }
}
}  // namespace

EquivalentRoughnessTable leave_out_strip(const EquivalentRoughnessTable& t, std::size_t skip,
                                         const BlockedForceGeometry& g) {
  const auto n_strips = static_cast<std::size_t>(t.strips), n = t.position.size();
  if (skip >= n_strips || n_strips < 2) throw std::logic_error("equivalent roughness: no strip to leave out");
  EquivalentRoughnessTable s = t;
  s.strips = t.strips - 1.0;
  s.height.clear();
  s.stiffness.clear();
  for (std::size_t si = 0; si < n_strips; ++si) {
    if (si == skip) continue;
    const auto first = static_cast<std::ptrdiff_t>(si * n), last = static_cast<std::ptrdiff_t>((si + 1) * n);
    s.height.insert(s.height.end(), t.height.begin() + first, t.height.begin() + last);
    s.stiffness.insert(s.stiffness.end(), t.stiffness.begin() + first, t.stiffness.begin() + last);
  }
  strip_mean_psd(s, g);
  return s;
}

namespace {
// What the build and its probe solve: the strip grid, the path's positions and the options.
struct PathSetup {
  contact::Grid strip_grid, window_grid;
  std::vector<double> positions;
  contact::SolverOptions opts;
  contact::EquivalentRoughnessOptions po;
};

PathSetup path_setup(const TableStudy& ts, const BlockedForceGeometry& geo) {
  const double dx = geo.cell;
  PathSetup p{{geo.nx, geo.ny, dx, dx}, {geo.window, geo.window, dx, dx}, {}, ts.stiffness.solver, {}};
  for (std::size_t j = geo.window / 2; j + geo.window / 2 < geo.nx; j += geo.step)
    p.positions.push_back(p.strip_grid.x(j));
  p.po.chunk_positions = kChunkPositions;
  // ER-1 to the solves' own accuracy (strip_load_tolerance).
  p.po.load_tolerance = strip_load_tolerance(p.opts);
  p.po.answer_tolerance = ts.equivalent_roughness.answer_tolerance;
  p.po.check_stride = kCheckStride;
  return p;
}
}  // namespace

TableProbe probe_equivalent_roughness(const TableStudy& ts, const BlockedForceGeometry& geo, double radius,
                                      double e_star, double load) {
  const PathSetup p = path_setup(ts, geo);
  const texture::Surface strip = study_strip(ts, StripGrid{geo.nx, geo.ny, geo.cell, geo.derived_cell}, 0);
  contact::ContactSolver solver(p.window_grid, e_star);
  // One whole chunk, as the build solves it (from the flat strip's field, then warm along the path):
  // its first positions cost more than the rest, so fewer positions would overstate the chunk.
  const std::size_t n = p.positions.size(), count = std::min(n, kChunkPositions);
  const std::vector<double> first(p.positions.begin(), p.positions.begin() + static_cast<std::ptrdiff_t>(count));
  TableProbe out;
  const std::clock_t start = std::clock();
  try {
    contact::equivalent_roughness(solver, p.strip_grid, strip.heights, radius, ts.stiffness.shape, first, load, p.opts,
                                  p.po);
  } catch (const std::invalid_argument& e) {  // as the build refuses it
    ts.blocked_force.origin(ts.blocked_force.window)
        .refuse(std::string(e.what()) + "; widen the window or the strip ([surface] ny)");
  }
  out.probe_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  out.positions = count;
  out.threads = build_threads(geo);
  out.seconds = static_cast<double>(ts.equivalent_roughness.strips) * out.probe_seconds * static_cast<double>(n) /
                static_cast<double>(count);
  return out;
}

EquivalentRoughnessTable build_equivalent_roughness(const TableStudy& ts, const BlockedForceGeometry& geo,
                                                    double radius, double e_star, double load, bool quiet) {
  const double dx = geo.cell;
  const std::size_t nx = geo.nx, ny = geo.ny;
  const auto n_strips = static_cast<std::size_t>(ts.equivalent_roughness.strips);
  const PathSetup setup = path_setup(ts, geo);
  const contact::Grid& strip_grid = setup.strip_grid;
  const std::vector<double>& positions = setup.positions;
  const contact::SolverOptions& opts = setup.opts;
  const contact::BallShape shape = ts.stiffness.shape;
  const contact::EquivalentRoughnessOptions& po = setup.po;
  if (!quiet)
    std::fprintf(stderr, "%sequivalent roughness: %s\n", ensemble::rank_prefix().c_str(),
                 equivalent_roughness_describe(ts, geo).c_str());
  EquivalentRoughnessTable t;
  t.position = positions;
  t.load = load;
  t.strips = static_cast<double>(n_strips);
  t.answer_tolerance = ts.equivalent_roughness.answer_tolerance;
  contact::ContactSolver solver(setup.window_grid, e_star);
  const auto start = std::chrono::steady_clock::now();
  ensemble::Progress progress("equivalent roughness strips", n_strips, quiet);  // bar and ETA
  progress.show_after(2.0);
  for (std::size_t si = 0; si < n_strips; ++si) {
    const texture::Surface strip = study_strip(ts, StripGrid{nx, ny, dx, geo.derived_cell}, si);
    contact::EquivalentRoughness r;
    try {
      r = contact::equivalent_roughness(solver, strip_grid, strip.heights, radius, shape, positions, load, opts, po);
    } catch (const std::invalid_argument& e) {
      ts.blocked_force.origin(ts.blocked_force.window)
          .refuse(std::string(e.what()) + "; widen the window or the strip ([surface] ny)");
    }
    require_converged(r.converged, r.max_error, "equivalent roughness: strip " + std::to_string(si));
    t.smooth_approach = r.smooth_approach;
    t.smooth_stiffness = r.smooth_stiffness;
    t.height.insert(t.height.end(), r.height.begin(), r.height.end());
    t.stiffness.insert(t.stiffness.end(), r.stiffness.begin(), r.stiffness.end());
    for (std::size_t j = 0; j < r.check_index.size(); ++j) {
      t.check_position.push_back(positions[r.check_index[j]]);
      t.check_residual.push_back(r.check_residual[j]);
    }
    if (!quiet)
      std::fprintf(stderr, "%sequivalent roughness: strip %zu of %zu, %d CG iterations, %.3g s wall\n",
                   ensemble::rank_prefix().c_str(), si + 1, n_strips, r.iterations,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    progress.advance();
  }
  progress.finish();  // the bar's "took" line (a log's only line of it)
  strip_mean_psd(t, geo);
  return t;
}

}  // namespace rollspec::stiffness
