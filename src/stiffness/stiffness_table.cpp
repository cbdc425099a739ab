#include "src/stiffness/stiffness_table.hpp"
#include "src/stiffness/table_location.hpp"
#include "src/stiffness/table_text.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "kernels/contact/geometry.hpp"
#include "kernels/contact/sweep.hpp"
#include "kernels/contact/version.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/rank_failure.hpp"
#include "src/ensemble/progress.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"
#include "src/texture/texture_keys.hpp"

namespace fs = std::filesystem;

namespace rollspec::stiffness {

namespace {

// Realisation ids of the ball's own roughness start here, clear of the flat's 0..R-1.
constexpr std::uint64_t kBallRealisations = 1u << 30;

// Datasets in checksum order.
const char* kDatasets[] = {"approach",           "force_mean",        "force_std",
                           "stiffness_mean",     "stiffness_std",     "contact_area_mean",
                           "plastic_cells_mean", "max_pressure_mean", "iterations_mean"};

std::vector<const std::vector<double>*> columns(const StiffnessTable& t) {
  return {&t.approach,          &t.force_mean,         &t.force_std,         &t.stiffness_mean, &t.stiffness_std,
          &t.contact_area_mean, &t.plastic_cells_mean, &t.max_pressure_mean, &t.iterations_mean};
}

}  // namespace

double StiffnessTable::approach_at(double load) const {
  for (std::size_t j = 1; j < approach.size(); ++j)
    if (force_mean[j] >= load) {
      const double f = (load - force_mean[j - 1]) / (force_mean[j] - force_mean[j - 1]);
      return approach[j - 1] + f * (approach[j] - approach[j - 1]);
    }
  return std::nan("");
}

double StiffnessTable::stiffness_at(double load) const {
  const double d = approach_at(load);
  for (std::size_t j = 1; j < approach.size(); ++j)
    if (approach[j] >= d) {
      const double f = (d - approach[j - 1]) / (approach[j] - approach[j - 1]);
      return stiffness_mean[j - 1] + f * (stiffness_mean[j] - stiffness_mean[j - 1]);
    }
  return std::nan("");
}

const TableKind kStiffnessTableKind = {
    kTableFileType, "/stiffness", "stiffness-", "stiffness table", {"seed 001", "Polonsky-Keer 1999", "D-6", "D-7"}};

std::string StiffnessTable::checksum() const { return io::hex16(column_hash(columns(*this))); }

CachedTable stiffness_cached_table(const TableStudy& t, double ball_radius, double effective_modulus) {
  const study::StiffnessSection& stiffness = t.stiffness;
  std::ostringstream in;
  in << "[contact kernel]\nversion = " << contact::kernel_version
     << "\n\n[ball]\nradius = " << io::exact_text(ball_radius)
     << "\neffective_modulus = " << io::exact_text(effective_modulus)
     << "\nshape = " << stiffness.value_text(stiffness.shape) << "\n\n[stiffness]\n";
  const auto& st = stiffness;
  for (const study::KeyValue* v :
       {&st.key_value(st.surface), &st.key_value(st.ball_rms), &st.key_value(st.approach_max), &st.key_value(st.steps),
        &st.key_value(st.solver.hardness), &st.key_value(st.solver.tolerance), &st.key_value(st.solver.max_iterations)})
    in << v->key << " = " << v->text << "\n";
  in << "realisations = " << (st.rough ? st.value_text(st.realisations) : "1")
     << "\nseed = " << st.value_text(st.table_seed) << "\n";  // the table seed
  // A leave-one-out sub-table (D-30): only when set, so every other table keeps its hash.
  if (stiffness.table_leave_out >= 0) in << "leave out = " << stiffness.value_text(stiffness.table_leave_out) << "\n";
  in << "\n[surface]\n";
  for (const char* k : {"method", "nx", "ny", "spacing", "anisotropy", "correlation_x", "correlation_y", "sigma"})
    in << k << " = " << t.surface.text(k) << "\n";
  // Eq. 26a changed the spectral surfaces of non-square grids only (square: the same bits), so only
  // their tables take a new hash.
  if (t.surface.nx != t.surface.ny) in << "mode power = rectangular cell mean (kernels/texture Eq. 26a)\n";
  if (stiffness.rough) {
    in << "\n[texture]\n";
    for (const auto& [key, value] : t.surface.texture_texts) in << key << " = " << value << "\n";
    in << "input files fingerprint = " << t.psd_fingerprint << "\n";
    if (!t.profile_derived_keys
             .empty()) {  // their values come from the fingerprinted profiles, not from the text above
      in << "from the profiles =";
      for (const auto& k : t.profile_derived_keys) in << " " << k;
      in << "\n";
    }
  }
  const std::string& explicit_path = stiffness.table;
  return CachedTable(kStiffnessTableKind, t.store, in.str(), explicit_path == "auto" ? "" : explicit_path);
}

void StiffnessTable::load_from(const io::Hdf5Reader& r) {
  std::vector<std::vector<double>*> cols = {&approach,           &force_mean,        &force_std,
                                            &stiffness_mean,     &stiffness_std,     &contact_area_mean,
                                            &plastic_cells_mean, &max_pressure_mean, &iterations_mean};
  for (std::size_t i = 0; i < cols.size(); ++i) *cols[i] = r.read(std::string("/stiffness/") + kDatasets[i]);
  for (const auto* c : cols)
    if (c->size() != approach.size() || c->size() < 2)
      throw data_error(r.path() + ": table columns have different lengths");
  ball_radius = r.double_attribute("/stiffness", "ball_radius");
  effective_modulus = r.double_attribute("/stiffness", "effective_modulus");
  hardness = r.double_attribute("/stiffness", "hardness");
  tolerance = r.double_attribute("/stiffness", "solver_tolerance");
  fit_coefficient = r.double_attribute("/stiffness/fit", "coefficient");
  fit_exponent = r.double_attribute("/stiffness/fit", "exponent");
  fit_max_relative_error = r.double_attribute("/stiffness/fit", "max_relative_error");
  realisations = static_cast<std::int64_t>(r.double_attribute("/stiffness", "realisations"));
}

namespace {

// Power-law fit P = c delta^n by least squares in log-log (a smooth monotone summary; the dynamics
// interpolate the table itself with a monotone cubic).
void fit_power_law(StiffnessTable& t) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t j = 1; j < t.approach.size(); ++j)
    if (t.force_mean[j] > 0) {
      const double x = std::log(t.approach[j]), y = std::log(t.force_mean[j]);
      sx += x, sy += y, sxx += x * x, sxy += x * y, m += 1;
    }
  if (m >= 2) {
    t.fit_exponent = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    t.fit_coefficient = std::exp((sy - t.fit_exponent * sx) / m);
    for (std::size_t j = 1; j < t.approach.size(); ++j)
      if (t.force_mean[j] > 0)
        t.fit_max_relative_error =
            std::max(t.fit_max_relative_error,
                     std::abs(t.fit_coefficient * std::pow(t.approach[j], t.fit_exponent) / t.force_mean[j] - 1.0));
  }
}

}  // namespace

namespace {

// Each surface's contact curve, surfaces[r][j] at approach step j (empty for the one left out).
struct SurfaceCurves {
  std::vector<double> deltas;
  std::vector<std::vector<contact::ContactResult>> surfaces;
};

SurfaceCurves surface_curves(const TableStudy& ts, double ball_radius, double effective_modulus, bool quiet) {
  contact::Grid grid;
  grid.nx = static_cast<std::size_t>(ts.surface.nx);
  grid.ny = static_cast<std::size_t>(ts.surface.ny);
  grid.dx = grid.dy = ts.surface.spacing;
  const study::StiffnessSection& stiffness = ts.stiffness;
  const bool is_rough = stiffness.rough;
  const int R = is_rough ? static_cast<int>(stiffness.realisations) : 1;
  const auto steps = static_cast<std::size_t>(stiffness.steps);
  const double dmax = stiffness.approach_max;
  const std::uint64_t seed = stiffness.table_seed;
  const auto shape = stiffness.shape;
  const double ball_rms = stiffness.ball_rms;
  if (ball_rms > 0.0 && !is_rough)
    stiffness.origin(stiffness.ball_rms).refuse("needs [stiffness] surface = rough (the flat's realisations)");
  const long long left_out = stiffness.table_leave_out;  // D-30: a leave-one-out sub-table
  if (left_out >= 0 && (!is_rough || R < 2 || left_out >= R))
    stiffness.origin(stiffness.table_leave_out)
        .refuse(
            "needs [stiffness] surface = rough and an index below [stiffness] "
            "realisations = " +
            std::to_string(R) + " (at least 2)");
  contact::SolverOptions opts = stiffness.solver;
  std::vector<double> deltas(steps);
  for (std::size_t j = 0; j < steps; ++j) deltas[j] = dmax * static_cast<double>(j + 1) / static_cast<double>(steps);

  // Realisation r runs on rank r mod ranks (OpenMP inside each rank); every rank then holds every
  // realisation's results and reduces them in realisation order, so the table has the same bits
  // for any rank and thread count.
  const int rank = ensemble::mpi_rank(), ranks = ensemble::mpi_size();
  std::vector<std::vector<contact::ContactResult>> results(static_cast<std::size_t>(R));
  std::exception_ptr failure;
  int mine = 0;
  for (int r = rank; r < R; r += ranks) mine += r != left_out;
  ensemble::Progress progress("stiffness realisations", static_cast<std::uint64_t>(mine), quiet,
                              ensemble::rank_prefix());
#pragma omp parallel
  {
    std::unique_ptr<contact::ContactSolver> solver;
#pragma omp for schedule(dynamic, 1)
    for (int r = 0; r < R; ++r) {
      if (failure || r % ranks != rank || r == left_out) continue;
      try {
        if (!solver) solver = std::make_unique<contact::ContactSolver>(grid, effective_modulus);
        texture::Surface surf;
        if (is_rough) ts.surfaces->generate(seed, static_cast<std::uint64_t>(r), surf, true);
        if (is_rough && ball_rms > 0.0) {
          // Rough on rough: the gap depends only on h_flat + h_ball (design §4); the ball's heights are
          // an independent realisation (ids offset by kBallRealisations) scaled to the ball's rms.
          texture::Surface ball;
          ts.surfaces->generate(seed, kBallRealisations + static_cast<std::uint64_t>(r), ball, true);
          double sq = 0.0;
          for (double v : ball.heights) sq += v * v;
          const double scale = ball_rms / std::sqrt(sq / static_cast<double>(ball.heights.size()));
          for (double& v : ball.heights) v *= scale;
          surf.heights = contact::composite_heights(surf.heights, ball.heights);
        }
        const auto gap = contact::ball_gap(grid, ball_radius, surf.heights, shape);
        // Rough: from first contact (the highest summit under the ball). Smooth: from the touching
        // position itself (min gap on the grid is dx^2 / 4R, not 0, when no cell centre is under the ball).
        const double first = is_rough ? *std::min_element(gap.begin(), gap.end()) : 0.0;
        std::vector<double> w(steps);
        for (std::size_t j = 0; j < steps; ++j) w[j] = first + deltas[j];
        results[static_cast<std::size_t>(r)] = contact::sweep(*solver, gap, w, opts);
        for (std::size_t j = 0; j < steps; ++j) {
          const auto& c = results[static_cast<std::size_t>(r)][j];
          if (!c.converged)
            throw data_error("stiffness table: the contact solve of realisation " + std::to_string(r) + ", step " +
                             std::to_string(j + 1) + " (approach " + io::exact_text(deltas[j]) +
                             " m) did not converge: error " + io::exact_text(c.error) + " > tolerance " +
                             io::exact_text(opts.tolerance) + " after " + std::to_string(c.iterations) +
                             " iterations; raise [stiffness] max_iterations or tolerance");
        }
        progress.advance();
      } catch (...) {
#pragma omp critical(rollspec_stiffness_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  ensemble::rethrow_on_every_rank(failure,
                                  ensemble::rank_prefix() + "stiffness table: another rank failed (see its message)");
  progress.finish();
  {
    // Six numbers per step and realisation travel to every rank.
    std::map<std::uint64_t, std::vector<double>> rows;
    for (int r = rank; r < R; r += ranks) {
      if (r == left_out) continue;
      auto& row = rows[static_cast<std::uint64_t>(r)];
      for (const auto& c : results[static_cast<std::size_t>(r)])
        row.insert(row.end(), {c.force, c.stiffness, c.contact_area, static_cast<double>(c.plastic_cells),
                               c.max_pressure, static_cast<double>(c.iterations)});
    }
    for (const auto& [r, row] : ensemble::allgather_rows(rows, 6 * steps)) {
      auto& res = results[static_cast<std::size_t>(r)];
      res.resize(steps);
      for (std::size_t j = 0; j < steps; ++j) {
        res[j].force = row[6 * j], res[j].stiffness = row[6 * j + 1], res[j].contact_area = row[6 * j + 2];
        res[j].plastic_cells = static_cast<std::size_t>(row[6 * j + 3]), res[j].max_pressure = row[6 * j + 4];
        res[j].iterations = static_cast<int>(row[6 * j + 5]);
      }
    }
  }

  return {deltas, std::move(results)};
}

// Mean and standard deviation over the surfaces but `left_out` (-1: none), in realisation order:
// the same bits for any thread count.
StiffnessTable reduce_table(const SurfaceCurves& curves, long long left_out, double ball_radius,
                            double effective_modulus, const contact::SolverOptions& opts) {
  const auto& results = curves.surfaces;
  const auto& deltas = curves.deltas;
  const std::size_t steps = deltas.size();
  const int R = static_cast<int>(results.size());
  StiffnessTable t;
  t.approach.push_back(0.0);
  for (auto* c : {&t.force_mean, &t.force_std, &t.stiffness_mean, &t.stiffness_std, &t.contact_area_mean,
                  &t.plastic_cells_mean, &t.max_pressure_mean, &t.iterations_mean})
    c->push_back(0.0);
  for (std::size_t j = 0; j < steps; ++j) {
    double f = 0, f2 = 0, k = 0, k2 = 0, a = 0, pc = 0, pm = 0, it = 0;
    for (std::size_t r = 0; r < results.size(); ++r) {
      if (static_cast<long long>(r) == left_out) continue;
      const auto& c = results[r][j];
      f += c.force, f2 += c.force * c.force, k += c.stiffness, k2 += c.stiffness * c.stiffness;
      a += c.contact_area, pc += static_cast<double>(c.plastic_cells), pm += c.max_pressure, it += c.iterations;
    }
    const double n = left_out >= 0 ? R - 1 : R;
    auto sd = [n](double s1, double s2) {
      return n > 1 ? std::sqrt(std::max(0.0, (s2 - s1 * s1 / n) / (n - 1))) : 0.0;
    };
    t.approach.push_back(deltas[j]);
    t.force_mean.push_back(f / n), t.force_std.push_back(sd(f, f2));
    t.stiffness_mean.push_back(k / n), t.stiffness_std.push_back(sd(k, k2));
    t.contact_area_mean.push_back(a / n), t.plastic_cells_mean.push_back(pc / n);
    t.max_pressure_mean.push_back(pm / n), t.iterations_mean.push_back(it / n);
  }
  fit_power_law(t);
  t.ball_radius = ball_radius;
  t.effective_modulus = effective_modulus;
  t.hardness = opts.hardness;
  t.realisations = left_out >= 0 ? R - 1 : R;
  t.tolerance = opts.tolerance;
  return t;
}

}  // namespace

StiffnessTable build_table(const TableStudy& ts, double ball_radius, double effective_modulus, bool quiet) {
  return reduce_table(surface_curves(ts, ball_radius, effective_modulus, quiet), ts.stiffness.table_leave_out,
                      ball_radius, effective_modulus, ts.stiffness.solver);
}

std::vector<std::string> resolve_leave_out_tables(const TableStudy& ts, double ball_radius, double effective_modulus,
                                                  bool rebuild, bool quiet) {
  std::vector<std::string> status(static_cast<std::size_t>(ts.stiffness.realisations));
  std::unique_ptr<SurfaceCurves> curves;  // every surface's curve, solved once for the first sub-table built
  TableStudy all = ts;
  all.stiffness = ts.stiffness.leaving_out(-1);
  for (long long i = 0; i < ts.stiffness.realisations; ++i) {
    TableStudy sub = ts;
    sub.stiffness = ts.stiffness.leaving_out(i);
    StiffnessTable t;
    stiffness_cached_table(sub, ball_radius, effective_modulus)
        .resolve(
            t, rebuild,
            [&](TableData& out) {
              if (!curves)
                curves = std::make_unique<SurfaceCurves>(surface_curves(all, ball_radius, effective_modulus, quiet));
              static_cast<StiffnessTable&>(out) =
                  reduce_table(*curves, i, ball_radius, effective_modulus, sub.stiffness.solver);
            },
            status[static_cast<std::size_t>(i)]);
  }
  return status;
}

void StiffnessTable::save_to(io::Hdf5Writer& w) const {
  const std::size_t n = approach.size();
  const char* units[] = {"m", "N", "N", "N/m", "N/m", "m^2", "1", "Pa", "1"};
  const char* what[] = {"approach from first contact",
                        "mean force over realisations",
                        "standard deviation of the force",
                        "mean frozen-set stiffness dP/d delta",
                        "standard deviation of the stiffness",
                        "mean real contact area",
                        "mean number of plastic cells (p = H)",
                        "mean of the maximum pressure",
                        "mean CG iterations of the contact solve"};
  const auto cols = columns(*this);
  for (std::size_t i = 0; i < cols.size(); ++i)
    w.write(std::string("/stiffness/") + kDatasets[i], {n}, cols[i]->data(), units[i], what[i]);
  w.make_scale("/stiffness/approach", "approach");
  for (std::size_t i = 1; i < cols.size(); ++i)
    w.attach_scale(std::string("/stiffness/") + kDatasets[i], "/stiffness/approach", 0);
  w.attribute("/stiffness", "ball_radius", ball_radius);
  w.attribute("/stiffness", "effective_modulus", effective_modulus);
  w.attribute("/stiffness", "hardness", hardness);
  w.attribute("/stiffness", "realisations", static_cast<double>(realisations));
  w.attribute("/stiffness", "solver_tolerance", tolerance);
  w.attribute("/stiffness", "stopping_rule",
              std::string("max_i C_ii |p_i - clamp(p_i - g_i / C_ii, 0, H)| / max_i (w - s_i) < solver_tolerance"));
  const double fit[] = {fit_coefficient, fit_exponent, fit_max_relative_error};
  w.write("/stiffness/fit/parameters", {3}, fit, "1",
          "P = coefficient * approach^exponent (SI), and its max relative error");
  w.attribute("/stiffness/fit", "form", std::string("P = coefficient * approach^exponent"));
  w.attribute("/stiffness/fit", "coefficient", fit_coefficient);
  w.attribute("/stiffness/fit", "exponent", fit_exponent);
  w.attribute("/stiffness/fit", "max_relative_error", fit_max_relative_error);
  w.attribute("/stiffness/fit", "tolerance", fit_tolerance);
  w.attribute("/stiffness/fit", "usable", std::string(fit_usable() ? "yes" : "no"));
  w.attribute("/stiffness/fit", "note",
              std::string("a summary of the table; the dynamics interpolate the table itself, never this fit"));
}

StiffnessTable resolve_table(const TableStudy& ts, double ball_radius, double effective_modulus, bool rebuild,
                             bool quiet, std::string& status) {
  const CachedTable cached = stiffness_cached_table(ts, ball_radius, effective_modulus);
  StiffnessTable t;
  cached.resolve(
      t, rebuild,
      [&](TableData& out) {
        static_cast<StiffnessTable&>(out) = build_table(ts, ball_radius, effective_modulus, quiet);
      },
      status);  // sets t.input_hash
  return t;
}

}  // namespace rollspec::stiffness
