#pragma once
// [stiffness]: the contact solver's settings and the stiffness-table stage (scenes stiffness and
// ball-on-beam), read once. The strip stages (blocked force, equivalent roughness, path table) and
// the stiffness table take their solver options from here, one parse of hardness, tolerance and
// max_iterations. The keys' canonical texts are kept for the cached tables' input texts (their hashes).
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class StiffnessSurface { rough, smooth };
enum class TableError { automatic, none, jackknife };

inline constexpr ChoiceTable<StiffnessSurface, 2> kStiffnessSurfaces{{
    {StiffnessSurface::rough, "rough", "[surface] realisations of the [texture] PSD"},
    {StiffnessSurface::smooth, "smooth", "a smooth flat"},
}};
inline constexpr ChoiceTable<contact::BallShape, 2> kBallShapes{{
    {contact::BallShape::Sphere, "sphere", "exact"},
    {contact::BallShape::Paraboloid, "paraboloid", "Hertz's"},
}};
inline constexpr ChoiceTable<TableError, 3> kTableErrors{{
    {TableError::automatic, "auto", "jackknife where the study's contact uses one random table, none otherwise"},
    {TableError::none, "none",
     "conditional on the table: the verdict then holds only for the surface the table was built on"},
    {TableError::jackknife, "jackknife",
     "the table's own sampling error, from the ensemble run again with each of the table's leave-one-out "
     "sub-tables (realisations + 1 ensembles on the same random streams, more realisations per sub-table where "
     "their own noise asks for them; kernels/spectral/README.md D-30, D-30f, D-31); needs a rough stiffness table "
     "([contact] law = table or literal, surface = rough; over its surfaces), an equivalent-roughness table "
     "([contact] filter = solver; over its [equivalent_roughness] strips) or a blocked-force table ([contact] "
     "blocked_force = solver; over the Welch segments of F0 along its strip)"},
}};

struct StiffnessSection : DeclaredSection<StiffnessSection> {
  std::string table, table_dir;  // as written: "auto" or a path; the cache directory
  StiffnessSurface surface = StiffnessSurface::rough;
  bool rough = true;  // surface = rough (else a smooth flat)
  contact::BallShape shape = contact::BallShape::Sphere;
  double ball_rms = 0.0, approach_max = 0.0;
  long long steps = 0, realisations = 0;
  std::uint64_t table_seed = 1;    // every table's surfaces and strips; never the study seed
  double table_shift = 0.0;        // standard errors of the table mean added to the law (not in its hash)
  long long table_leave_out = -1;  // surface left out of the stiffness table's mean (-1: none; in its hash when set)
  TableError table_error = TableError::automatic;
  bool table_jackknife = false;   // table_error = jackknife: the intervals include the table's own error (D-30)
  bool table_error_auto = false;  // table_error = auto (the default): jackknife where the study has one random table
  contact::SolverOptions solver;  // hardness (0: none, so infinite), tolerance, max_iterations

  static SectionKeys<StiffnessSection> declare();
  void finish();                                              // rough, the solver's hardness, the table error's flags
  static std::string table_error_setting(TableError v);       // "stiffness.table_error=<spelling>", a --set text
  static std::string table_setting(const std::string& path);  // "stiffness.table=<path>", a --set text
  // The section of leave-one-out sub-table `i` (D-30): table_leave_out = i, its own cached file
  // (table = auto) and no jackknife of its own, as `--set` of those three keys would give.
  StiffnessSection leaving_out(long long i) const;
  // Those three keys as `--set` texts, for a study that runs sub-table `i`.
  static std::vector<std::string> leave_out_sets(long long i);
};

}  // namespace rollspec::study
