// Scene `ball-on-beam`'s stages: the texture, surface, contact tables, dynamics, spectra and reference of its
// pipeline, each table a stage whose resolution completes the contact law it feeds (ball_on_beam_contact.hpp);
// the checks of what a table jackknife can leave out; prepare().
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "src/io/run_warning.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_scene.hpp"
#include "src/stiffness/strip_equivalent_roughness.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::scenes {

using namespace study;

// plan: the equivalent-roughness table of filter = solver, when it is not cached, from a few of its
// solves (its cost follows the texture's listed cells, which the plan's model cannot see).
std::vector<TableEstimate> BallOnBeam::probe_tables(double max_probe_seconds) const {
  if (!filter_tables_) return {};
  for (const auto& p : plan())
    if (p.stage == "equivalent_roughness" && p.status != StageStatus::run) return {};
  const stiffness::BlockedForceGeometry g = blocked_force_grid();
  if (stiffness::equivalent_roughness_probe_seconds(*filter_tables_, g) > max_probe_seconds) return {};
  const stiffness::TableProbe t = stiffness::probe_equivalent_roughness(
      *filter_tables_, g, b_.model.contact.radius, b_.model.contact.effective_modulus, b_.weight());
  const std::string how =
      io::formatted("the first %zu positions of strip 0 solved in %.2g s CPU", t.positions, t.probe_seconds);
  return {{"equivalent_roughness", t.seconds, t.threads, how}};
}

// D-30: one random table, of at least 2 surfaces, strips or Welch segments of F0.
void BallOnBeam::check_table_jackknife() const {
  const bool stiffness_table = uses_table() && b_.stiffness.rough, strips = solver_filter() && !b_.strip_line;
  if (stiffness_table && strips)
    b_.stiffness.origin(b_.stiffness.table_error)
        .refuse(
            "jackknife takes one table; this study has a rough stiffness table and an equivalent-roughness table "
            "([contact] filter = solver); allowed here: none, or one of the two");
  if (!(stiffness_table && b_.stiffness.realisations >= 2) && !(strips && b_.equivalent_roughness_strips >= 2) &&
      !(blocked_solver() && stiffness::f0_segments(blocked_force_grid()).segments >= 2))
    b_.stiffness.origin(b_.stiffness.table_error)
        .refuse(
            "jackknife needs a rough stiffness table of at least 2 surfaces ([contact] law = table or literal, "
            "[stiffness] surface = rough, realisations >= 2), an equivalent-roughness table of at least 2 strips "
            "([contact] filter = solver, [equivalent_roughness] line = synthesised, strips >= 2) or a blocked-force "
            "table of at least 2 Welch segments ([contact] blocked_force = solver); allowed here: none");
}

// [blocked_force] leave_out (D-30d): a Welch segment of the solver's F0, which must exist.
void BallOnBeam::check_blocked_force_leave_out() const {
  const long long i = b_.blocked_force.leave_out;
  if (i < 0) return;
  if (!blocked_solver())
    b_.blocked_force.origin(b_.blocked_force.leave_out)
        .refuse(
            "leaves a Welch segment out of the blocked-force table of [contact] blocked_force = solver, which this "
            "study does not use; allowed here: -1");
  const std::size_t n = stiffness::f0_segments(blocked_force_grid()).segments;
  if (static_cast<std::size_t>(i) >= n)
    b_.blocked_force.origin(b_.blocked_force.leave_out)
        .refuse("leaves out a Welch segment F0's path does not have; allowed: -1 .. " +
                std::to_string(static_cast<long long>(n) - 1) +
                " (the path's segments, `rollspec plan` shows its positions and "
                "segment)");
}

// D-30, D-31: explicit jackknife (checked in the constructor), or auto with exactly one random table
// of at least two units. Sub-tables and legs of a blocked-force or equivalent-roughness leave-out run none.
bool BallOnBeam::estimates_table_error() const {
  if (b_.stiffness.table_jackknife) return true;
  if (!b_.stiffness.table_error_auto || b_.blocked_force.leave_out >= 0 || b_.equivalent_roughness_leave_out >= 0)
    return false;
  const int tables = (uses_table() && b_.stiffness.rough && b_.stiffness.realisations >= 2) +
                     (solver_filter() && !b_.strip_line && b_.equivalent_roughness_strips >= 2) +
                     (blocked_solver() && stiffness::f0_segments(blocked_force_grid()).segments >= 2);
  return tables == 1;
}

// The tables drawn from random surfaces or strips that every realisation shares: the intervals are
// conditional on them (kernels/spectral/README.md D-28).
std::string BallOnBeam::random_tables() const {
  std::string out;
  auto add = [&out](const char* name) { out += (out.empty() ? "" : ", ") + std::string(name); };
  if (uses_table() && b_.stiffness.rough) add("stiffness table");
  if (blocked_solver()) add("blocked-force table");
  if (solver_filter()) add("equivalent-roughness table");
  if (b_.path_law()) add("path table");
  return out;
}

// texture, surface, stiffness_table, blocked_force, dynamics, spectra: the tables are stage
// objects whose inspection `plan` prints and whose resolution prepare() runs.
void BallOnBeam::add_pipeline_stages(const stiffness::TableStudy& tables) {
  if (b_.path_law())
    add_stages(
        {{"texture", StageStatus::skipped, "law = path: the path table's strip is the roughness (no line texture)"}});
  else if (b_.strip_line)
    add_stages({{"texture", StageStatus::skipped,
                 "equivalent_roughness.line = strip: h_eq of strip 0 along the path is the line (no synthesis)"}});
  else
    add_stages({{"texture", StageStatus::run,
                 "beam line texture per realisation from [texture] (" + b_.psd.description + "); " +
                     contact_filter_description(b_)}});
  std::unique_ptr<TableStage> table;
  if (uses_table()) {
    const double radius = b_.model.contact.radius, e_star = b_.model.contact.effective_modulus;
    table = std::make_unique<TableStage>(
        "stiffness_table", stiffness::stiffness_cached_table(tables, radius, e_star),
        [] { return std::make_unique<stiffness::StiffnessTable>(); },
        [tables, radius, e_star](stiffness::TableData& out, bool quiet) {
          static_cast<stiffness::StiffnessTable&>(out) = stiffness::build_table(tables, radius, e_star, quiet);
        },
        [this](const stiffness::TableData& t, const std::string& status, bool quiet) {
          use_stiffness_table(static_cast<const stiffness::StiffnessTable&>(t), status, quiet);
        });
  }
  const TableStage* t = table.get();
  add_stage(std::make_unique<DerivedStage>([t] {
    const bool valid = t && t->state() == stiffness::TableState::valid;
    return StagePlan{"surface", t && !valid ? StageStatus::run : StageStatus::skipped,
                     !t      ? "the point-contact laws need no isotropic surface"
                     : valid ? "inside the cached stiffness table"
                             : "isotropic surfaces for the stiffness table"};
  }));
  if (table)
    add_stage(std::move(table));
  else
    add_stages({{"stiffness_table", StageStatus::skipped,
                 linearised()    ? "linearised law: k0 from [contact]"
                 : b_.path_law() ? "path law: P(delta, xi) from the path table"
                                 : "hertz law: analytic, needs no table"}});
  if (blocked_solver()) {
    // The strip's grid: the study's keys where set, else derived from the contact radius and the
    // texture; the path step at most v / f_s so F0 reaches the output's Nyquist frequency.
    const stiffness::BlockedForceGeometry grid = blocked_force_grid();
    add_contact_table_stage("blocked_force", tables, grid, &stiffness::blocked_force_cached_table,
                            &stiffness::build_blocked_force, &BallOnBeam::use_blocked_force, grid.describe());
  } else {
    add_stages({{"blocked_force", linearised() ? StageStatus::run : StageStatus::skipped,
                 linearised() ? "F0(t) = W + k0 h_patch(v t) per realisation (linear contact spring)"
                              : "only the linearised law uses F0"}});
  }
  if (solver_filter() && b_.strip_line) {
    // line = strip: h_eq of strip 0 on the path table's grid and strip (the strip law = path uses), at
    // the linear rule's positions (a/4: the point law's line is linear between them).
    const stiffness::PathTableGeometry grid = path_grid(true);
    add_contact_table_stage("equivalent_roughness", tables, grid, &stiffness::strip_equivalent_roughness_cached_table,
                            &stiffness::build_strip_equivalent_roughness, &BallOnBeam::use_strip_equivalent_roughness,
                            stiffness::strip_equivalent_roughness_describe(grid));
  } else if (solver_filter()) {
    // filter = solver (kernels/contact ER-1..ER-6): h_eq on the blocked-force grid, the path step
    // at most v / f_s so the h_eq PSD reaches the band limit (B40).
    const stiffness::BlockedForceGeometry grid = blocked_force_grid();
    add_contact_table_stage("equivalent_roughness", tables, grid, &stiffness::equivalent_roughness_cached_table,
                            &stiffness::build_equivalent_roughness, &BallOnBeam::use_equivalent_roughness,
                            stiffness::equivalent_roughness_describe(tables, grid));
  }
  if (b_.path_law()) {
    // law = path (kernels/beam B41-B46): P(delta, xi) of strip 0 along the ball's whole path.
    const stiffness::PathTableGeometry grid = path_grid();
    add_contact_table_stage("path_table", tables, grid, &stiffness::path_cached_table, &stiffness::build_path_table,
                            &BallOnBeam::use_path_table,
                            grid.describe() +
                                "; every realisation rolls over this one strip (nothing else is random: K > 1 "
                                "repeats the same run)");
  }
  add_stages({{"dynamics", StageStatus::run,
               b_.dopri ? "Dormand-Prince 5(4) reference" : "exact modal step per mode, implicit contact force"},
              {"spectra", StageStatus::run, "Welch PSDs of sensors, contact force and ball; ensemble mean"},
              {"reference", writes_reference() ? StageStatus::run : StageStatus::skipped,
               !linearised()  ? "only the linearised law has a frequency-domain reference"
               : b_.reference ? "frequency-domain PSD of the linearised model, its expected Welch estimate and the "
                                "range of the ensemble mean, once after the ensemble"
                              : "[output] reference = false"}});
}

// The path table's grid along the ball's whole path (law = path, and line = strip on its grid, with
// the linear rule's step).
stiffness::PathTableGeometry BallOnBeam::path_grid(bool strip_line) const {
  study::PathTableSection section = b_.path_table;
  if (strip_line) section.interpolation = study::PathInterpolation::linear;
  return stiffness::path_table_geometry(section, b_.blocked_force, b_.strip_surface, b_.texture_psd,
                                        b_.model.contact.radius, b_.model.contact.effective_modulus, b_.weight(),
                                        b_.model.traverse.x_end - b_.model.traverse.x_start);
}

// The strip's grid: the study's keys where set, else derived from the contact radius and the
// texture; the path step at most v / f_s so F0 (and h_eq) reach the output's Nyquist frequency.
stiffness::BlockedForceGeometry BallOnBeam::blocked_force_grid() const {
  return stiffness::blocked_force_geometry(b_.blocked_force, b_.strip_surface, b_.texture_psd, b_.model.contact.radius,
                                           b_.model.contact.effective_modulus, b_.weight(),
                                           b_.model.traverse.speed / b_.model.sample_rate);
}

// A cached table of strip 0 that the contact law takes: its file and hash from (study, grid, R, E*,
// W), built from the same, completed by a use_* member.
template <class Table, class Grid>
void BallOnBeam::add_contact_table_stage(
    const char* name, const stiffness::TableStudy& s, const Grid& grid,
    stiffness::CachedTable (*cached)(const stiffness::TableStudy&, const Grid&, double, double, double),
    Table (*build)(const stiffness::TableStudy&, const Grid&, double, double, double, bool),
    void (BallOnBeam::*use)(const Table&, const std::string&, bool), std::string detail) {
  const double radius = b_.model.contact.radius, e_star = b_.model.contact.effective_modulus, weight = b_.weight();
  add_stage(std::make_unique<TableStage>(
      name, cached(s, grid, radius, e_star, weight), [] { return std::make_unique<Table>(); },
      [s, grid, radius, e_star, weight, build](stiffness::TableData& out, bool quiet) {
        static_cast<Table&>(out) = build(s, grid, radius, e_star, weight, quiet);
      },
      [this, use](const stiffness::TableData& t, const std::string& status, bool quiet) {
        (this->*use)(static_cast<const Table&>(t), status, quiet);
      },
      std::move(detail)));
}

void BallOnBeam::prepare(bool quiet, bool rebuild) {
  quiet_ = quiet;
  resolve_stages(quiet, rebuild);      // the tables' use_* complete the contact law
  if (jackknifes_stiffness_table()) {  // D-30: every sub-table cached now, from one solve per surface
    const auto status = stiffness::resolve_leave_out_tables(*tables_, b_.model.contact.radius,
                                                            b_.model.contact.effective_modulus, rebuild, quiet);
    if (!quiet)
      std::fprintf(stderr, "stiffness table: %zu leave-one-out sub-tables for the jackknife (first: %s)\n",
                   status.size(), status.empty() ? "-" : status[0].c_str());
  }
  model_ = std::make_unique<const beam::BallOnBeamModel>(resolved_model(b_, contact_));
  integrator_ = std::make_unique<beam::ExactStepIntegrator>(*model_, b_.step);
  excitation_ = make_ball_on_beam_excitation(b_, contact_, lines_, static_cast<int>(workspaces_.size()));
}

// The tables' stages: each completes the resolved contact (ball_on_beam_contact.hpp) and says so.
void BallOnBeam::use_stiffness_table(const stiffness::StiffnessTable& t, const std::string& status, bool quiet) {
  // What the band intervals include (kernels/spectral/README.md Eq. T-1 to T-4).
  if (!quiet)
    std::fprintf(stderr,
                 "stiffness table: %s (%lld surfaces, [stiffness] table_seed = %s, table_shift = %g standard "
                 "errors)\nintervals: %s\n",
                 status.c_str(), static_cast<long long>(t.realisations),
                 b_.stiffness.value_text(b_.stiffness.table_seed).c_str(), b_.stiffness.table_shift,
                 jackknifes_stiffness_table()
                     ? "the realisations' and the table's own sampling error (a jackknife over its surfaces: the "
                       "ensemble runs once more per surface; kernels/spectral/README.md D-30)"
                     : "the realisations' sampling error only, conditional on this table; its own sampling error "
                       "is not included ([stiffness] table_error = jackknife includes it; kernels/spectral/README.md "
                       "D-28, D-30)");
  take_stiffness_table(b_, t, contact_);
}

void BallOnBeam::use_path_table(const stiffness::PathTableData& t, const std::string& status, bool quiet) {
  take_path_table(b_, t, contact_);
  if (!quiet)
    std::fprintf(stderr,
                 "path table: %s (%zu approaches x %zu positions; mean static approach %.4g m from the mean plane)\n",
                 status.c_str(), t.approach.size(), t.position.size(), contact_.static_compression);
}

void BallOnBeam::use_strip_equivalent_roughness(const stiffness::EquivalentRoughnessTable& t, const std::string& status,
                                                bool quiet) {
  if (!quiet)
    std::fprintf(stderr, "equivalent roughness table: %s (strip 0, %zu positions, delta_smooth = %.4g m)\n",
                 status.c_str(), t.position.size(), t.smooth_approach);
  take_strip_line(b_, t, contact_);
  apply_equivalent_stiffness(t, quiet);
}

void BallOnBeam::apply_equivalent_stiffness(const stiffness::EquivalentRoughnessTable& t, bool quiet) {
  const double rho = take_equivalent_stiffness(b_, t, contact_);
  if (rho > 0.0 && !quiet)
    std::fprintf(stderr,
                 "equivalent stiffness: the strips' mean contact stiffness at the weight is %.4g of the smooth "
                 "strip's; the point law is stretched along the approach by 1/%.4g (ER-7)\n",
                 rho, rho);
}

// filter = solver: the line is drawn from h_eq's PSD, so its generator is made again.
// [equivalent_roughness] leave_out = i: the cached table without strip i (D-30; no new solve).
void BallOnBeam::use_equivalent_roughness(const stiffness::EquivalentRoughnessTable& full, const std::string& status,
                                          bool quiet) {
  const long long skip = b_.equivalent_roughness_leave_out;
  std::optional<stiffness::EquivalentRoughnessTable> sub;  // only a sub-table is a new table
  if (skip >= 0) sub = stiffness::leave_out_strip(full, static_cast<std::size_t>(skip), blocked_force_grid());
  const stiffness::EquivalentRoughnessTable& t = sub ? *sub : full;
  if (!quiet)
    std::fprintf(stderr, "equivalent roughness table: %s (%g strips x %zu positions, delta_smooth = %.4g m%s)\n",
                 status.c_str(), t.strips, t.position.size(), t.smooth_approach,
                 skip >= 0 ? (", strip " + std::to_string(skip) + " left out").c_str() : "");
  take_equivalent_roughness_psd(b_, t, contact_);
  apply_equivalent_stiffness(t, quiet);
  lines_ = texture_io::line_generator(b_.line_keys, contact_.line_psd, b_.spacing, b_.line_samples);
}

// [blocked_force] leave_out = i: the cached table without Welch segment i of F0 (D-30d; no new solve).
void BallOnBeam::use_blocked_force(const stiffness::BlockedForceTable& full, const std::string& status, bool quiet) {
  const long long skip = b_.blocked_force.leave_out;
  std::optional<stiffness::BlockedForceTable> sub;  // only a sub-table is a new table
  if (skip >= 0) sub = stiffness::leave_out_segment(full, static_cast<std::size_t>(skip), blocked_force_grid());
  if (!quiet)
    std::fprintf(stderr, "blocked force table: %s (k0 = %.4g N/m, d0 = %.4g m%s)\n", status.c_str(), full.k0,
                 full.approach, skip >= 0 ? (", Welch segment " + std::to_string(skip) + " left out").c_str() : "");
  take_blocked_force(b_, sub ? *sub : full, contact_);
}

}  // namespace rollspec::scenes
