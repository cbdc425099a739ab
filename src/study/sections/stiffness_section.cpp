#include "src/study/sections/stiffness_section.hpp"

#include <limits>
#include <stdexcept>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> StiffnessSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      text_key("stiffness", "table", "table file: auto (<table_dir>/stiffness-<input hash>.h5) or a path",
               std::string("auto")),
      text_key("stiffness", "table_dir", "directory of cached tables, relative to the study file",
               std::string("tables")),
      choice_key("stiffness", "surface", "the flat of the table's contact solves", StiffnessSurface::rough,
                 kStiffnessSurfaces),
      choice_key("stiffness", "shape", "ball geometry", contact::BallShape::Sphere, kBallShapes),
      real_key("stiffness", "ball_rms", "m",
               "rms roughness of the ball (rough on rough: composite surface h_flat + h_ball, the ball's heights from "
               "the [texture] PSD's shape scaled to this rms); 0: smooth ball",
               std::string("0"), 0.0, inf),
      real_key("stiffness", "approach_max", "m", "largest approach from first contact", std::string("0.5e-6"), 0.0, inf,
               false),
      integer_key("stiffness", "steps", "approach steps (uniform, warm-started)", std::string("20"), 2, 10000),
      integer_key("stiffness", "realisations", "rough-surface realisations averaged", std::string("10"), 1, 100000),
      real_key("stiffness", "hardness", "Pa", "pressure cap H (plastic flow); 0: none (elastic)", std::string("0"), 0.0,
               inf),
      real_key("stiffness", "tolerance", "-", "stopping rule: relative complementarity error of each contact solve",
               std::string("1e-8"), 1e-15, 1e-2),
      integer_key("stiffness", "max_iterations", "CG iterations allowed per contact solve", std::string("20000"), 10,
                  1e7),
      integer_key("stiffness", "table_seed",
                  "seed of every contact table's surfaces and strips (their own Philox streams, keyed by (table_seed, "
                  "index)); independent of [study] seed, so another study seed reuses the tables",
                  std::string("1"), 0, 9.0e18),
      real_key("stiffness", "table_shift", "-",
               "law = table / literal: shift the table's mean force / stiffness by this many standard errors of its "
               "mean over the surfaces (std / sqrt(realisations)); runs at +1 and -1 with the same [study] seed "
               "give the band levels' response to that shift (kernels/spectral/README.md D-28: it understates the "
               "table's share)",
               std::string("0"), -10.0, 10.0),
      integer_key("stiffness", "table_leave_out",
                  "surface index (0 .. realisations - 1) left out of the stiffness table's mean: a leave-one-out "
                  "sub-table for the jackknife of the table's own error (kernels/spectral/README.md D-30); -1: none",
                  std::string("-1"), -1, 99999),
      choice_key("stiffness", "table_error",
                 "what `run`'s intervals, compare and fit include besides the realisations' scatter",
                 TableError::automatic, kTableErrors),
  };
}

StiffnessSection StiffnessSection::parse(const KeyReader& s) {
  StiffnessSection t;
  t.rough = read_choice(s, "stiffness.surface", kStiffnessSurfaces) == StiffnessSurface::rough;
  t.shape = read_choice(s, "stiffness.shape", kBallShapes);
  t.ball_rms = s.real("stiffness.ball_rms");
  t.approach_max = s.real("stiffness.approach_max");
  t.steps = s.integer("stiffness.steps");
  t.realisations = s.integer("stiffness.realisations");
  const double h = s.real("stiffness.hardness");
  t.solver.hardness = h > 0.0 ? h : std::numeric_limits<double>::infinity();
  t.solver.tolerance = s.real("stiffness.tolerance");
  t.solver.max_iterations = static_cast<int>(s.integer("stiffness.max_iterations"));
  t.table_seed = static_cast<std::uint64_t>(s.integer("stiffness.table_seed"));
  t.table_shift = s.real("stiffness.table_shift");
  t.table_leave_out = s.integer("stiffness.table_leave_out");
  t.table_leave_out_origin = {s.where("stiffness.table_leave_out")};
  const TableError table_error = read_choice(s, "stiffness.table_error", kTableErrors);
  t.table_jackknife = table_error == TableError::jackknife;
  t.table_error_auto = table_error == TableError::automatic;
  t.table_error_origin = {s.where("stiffness.table_error")};
  if (t.table_leave_out >= 0) t.table_error_auto = false;  // a sub-table itself: no jackknife of its own
  if (t.table_jackknife && t.table_leave_out >= 0)
    t.table_error_origin.refuse(
        "jackknife runs every leave-one-out sub-table itself; allowed with it: "
        "[stiffness] table_leave_out = -1 (" +
        t.table_leave_out_origin.where + ")");
  t.ball_rms_origin = {s.where("stiffness.ball_rms")};
  t.approach_max_origin = {s.where("stiffness.approach_max")};
  t.table_shift_origin = {s.where("stiffness.table_shift")};
  t.table_origin = {s.where("stiffness.table")};
  t.table_dir_origin = {s.where("stiffness.table_dir")};
  for (const auto& k : keys()) t.texts_[k.key] = s.text(k.full_name());
  return t;
}

const std::string& StiffnessSection::text(const std::string& key) const {
  const auto it = texts_.find(key);
  if (it == texts_.end()) throw std::logic_error("not a [stiffness] key: " + key);
  return it->second;
}

StiffnessSection StiffnessSection::leaving_out(long long i) const {
  StiffnessSection t = *this;
  t.table_leave_out = i;
  t.table_jackknife = false;
  t.table_error_auto = false;
  t.texts_["table_leave_out"] = std::to_string(i);
  t.texts_["table"] = "auto";
  t.texts_["table_error"] = "none";
  return t;
}

std::string StiffnessSection::table_error_setting(TableError v) {
  return choice_setting("stiffness.table_error", kTableErrors, v);
}

std::vector<std::string> StiffnessSection::leave_out_sets(long long i) {
  return {"stiffness.table_leave_out=" + std::to_string(i), "stiffness.table=auto",
          table_error_setting(TableError::none)};
}

}  // namespace rollspec::study
