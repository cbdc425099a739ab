#include "src/study/sections/stiffness_section.hpp"

#include <limits>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<StiffnessSection> StiffnessSection::declare() {
  using T = StiffnessSection;
  using O = contact::SolverOptions;
  return SectionKeys<T>("stiffness")
      .text("table", &T::table, "table file: auto (<table_dir>/stiffness-<input hash>.h5) or a path", "auto")
      .text("table_dir", &T::table_dir, "directory of cached tables, relative to the study file", "tables")
      .choice("surface", &T::surface, "the flat of the table's contact solves", StiffnessSurface::rough,
              kStiffnessSurfaces)
      .choice("shape", &T::shape, "ball geometry", contact::BallShape::Sphere, kBallShapes)
      .real("ball_rms", &T::ball_rms, "m",
            "rms roughness of the ball (rough on rough: composite surface h_flat + h_ball, the ball's heights from "
            "the [texture] PSD's shape scaled to this rms); 0: smooth ball",
            "0", at_least(0.0))
      .real("approach_max", &T::approach_max, "m", "largest approach from first contact", "0.5e-6", above(0.0))
      .integer("steps", &T::steps, "approach steps (uniform, warm-started)", "20", 2, 10000)
      .integer("realisations", &T::realisations, "rough-surface realisations averaged", "10", 1, 100000)
      .real("hardness", nested(&T::solver, &O::hardness), "Pa", "pressure cap H (plastic flow); 0: none (elastic)", "0",
            at_least(0.0))
      .real("tolerance", nested(&T::solver, &O::tolerance), "-",
            "stopping rule: relative complementarity error of each contact solve", "1e-8", within(1e-15, 1e-2))
      .integer("max_iterations", nested(&T::solver, &O::max_iterations), "CG iterations allowed per contact solve",
               "20000", 10, 1e7)
      .integer("table_seed", &T::table_seed,
               "seed of every contact table's surfaces and strips (their own Philox streams, keyed by (table_seed, "
               "index)); independent of [study] seed, so another study seed reuses the tables",
               "1", 0, 9.0e18)
      .real("table_shift", &T::table_shift, "-",
            "law = table / literal: shift the table's mean force / stiffness by this many standard errors of its "
            "mean over the surfaces (std / sqrt(realisations)); runs at +1 and -1 with the same [study] seed "
            "give the band levels' response to that shift (kernels/spectral/README.md D-28: it understates the "
            "table's share)",
            "0", within(-10.0, 10.0))
      .integer("table_leave_out", &T::table_leave_out,
               "surface index (0 .. realisations - 1) left out of the stiffness table's mean: a leave-one-out "
               "sub-table for the jackknife of the table's own error (kernels/spectral/README.md D-30); -1: none",
               "-1", -1, 99999)
      .choice("table_error", &T::table_error,
              "what `run`'s intervals, compare and fit include besides the realisations' scatter",
              TableError::automatic, kTableErrors);
}
template struct DeclaredSection<StiffnessSection>;

void StiffnessSection::finish() {
  rough = surface == StiffnessSurface::rough;
  if (!(solver.hardness > 0.0)) solver.hardness = std::numeric_limits<double>::infinity();
  table_jackknife = table_error == TableError::jackknife;
  table_error_auto = table_error == TableError::automatic && table_leave_out < 0;  // a sub-table: none of its own
  if (table_jackknife && table_leave_out >= 0)
    origin(table_error)
        .refuse(
            "jackknife runs every leave-one-out sub-table itself; allowed with it: "
            "[stiffness] table_leave_out = -1 (" +
            origin(table_leave_out).where + ")");
}

StiffnessSection StiffnessSection::leaving_out(long long i) const {
  StiffnessSection t = *this;
  t.table_leave_out = i;
  t.table = "auto";
  t.table_error = TableError::none;
  t.table_jackknife = false;
  t.table_error_auto = false;
  t.set_text(t.table_leave_out, std::to_string(i));
  t.set_text(t.table, t.table);
  t.set_text(t.table_error, spelling_of(kTableErrors, t.table_error));
  return t;
}

std::string StiffnessSection::table_error_setting(TableError v) {
  return choice_setting(declared().full_name(&StiffnessSection::table_error), kTableErrors, v);
}

std::string StiffnessSection::table_setting(const std::string& path) {
  return declared().full_name(&StiffnessSection::table) + "=" + path;
}

std::vector<std::string> StiffnessSection::leave_out_sets(long long i) {
  return {declared().full_name(&StiffnessSection::table_leave_out) + "=" + std::to_string(i), table_setting("auto"),
          table_error_setting(TableError::none)};
}

}  // namespace rollspec::study
