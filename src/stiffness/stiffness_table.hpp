#pragma once
// Contact stiffness tables (design §4; seed 001 §3.2-3.3, Eq. 11-13): the force P(delta), stiffness
// k(delta) = dP/d delta (frozen-set solve) and real contact area of a smooth ball pressed onto
// rough-surface realisations by the elastic-plastic half-space solver, mean and standard deviation
// over realisations. delta is the approach from first contact (the highest summit under the ball;
// for a smooth flat, from the touching position);
// the roughness the ball rolls over enters the dynamics separately through the line texture (D-1).
//
// The table is a CachedTable (cached_table.hpp): reused only when its canonical inputs, schema,
// contact kernel version and data checksum match.
#include <cstdint>
#include <string>
#include <vector>

#include "src/stiffness/cached_table.hpp"
#include "src/stiffness/table_study.hpp"

namespace rollspec::stiffness {

constexpr const char* kTableFileType = "rollspec-stiffness-table";
extern const TableKind kStiffnessTableKind;

struct StiffnessTable : TableData {
  std::vector<double> approach;  // delta_j, m (first entry 0)
  std::vector<double> force_mean, force_std;
  std::vector<double> stiffness_mean, stiffness_std;
  std::vector<double> contact_area_mean, plastic_cells_mean, max_pressure_mean, iterations_mean;
  double ball_radius = 0.0, effective_modulus = 0.0, hardness = 0.0;  // m, Pa, Pa (inf: elastic)
  std::int64_t realisations = 0;
  double tolerance = 0.0;  // solver stopping rule (complementarity error)
  double fit_coefficient = 0.0, fit_exponent = 0.0, fit_max_relative_error = 0.0;  // P = c delta^n
  // A summary only: the dynamics interpolate the table itself. A fit whose largest relative error
  // over the table's nonzero forces exceeds this is flagged as not usable wherever it is shown.
  static constexpr double fit_tolerance = 0.05;
  bool fit_usable() const { return fit_max_relative_error <= fit_tolerance; }
  // Approach and stiffness where the mean force equals `load` (monotone interpolation of the table).
  double approach_at(double load) const;
  double stiffness_at(double load) const;

  void load_from(const io::Hdf5Reader& r) override;
  void save_to(io::Hdf5Writer& w) const override;
  std::string checksum() const override;
};

// What a study asks for (no computation): the canonical inputs ([stiffness] keys, surfaces, PSD,
// contact pair, contact kernel version) and where the table lives ([stiffness] table, or
// <table_dir>/stiffness-<hash>.h5).
CachedTable stiffness_cached_table(const TableStudy& t, double ball_radius, double effective_modulus);

// Builds the table (OpenMP over surface realisations). Throws UserError (exit 65) naming the
// realisation and step if a contact solve does not converge.
StiffnessTable build_table(const TableStudy& t, double ball_radius, double effective_modulus, bool quiet);

// The stage as scenes use it: reuse a valid table, build a missing one, refuse a mismatched or
// damaged one (exit 65, naming the differences) unless `rebuild`. `status` says which.
StiffnessTable resolve_table(const TableStudy& t, double ball_radius, double effective_modulus, bool rebuild,
                             bool quiet, std::string& status);

// [stiffness] table_error = jackknife (kernels/spectral/README.md D-30): every leave-one-out
// sub-table of t's surfaces, each a cached table of its own (the file `table_leave_out = i` names,
// with the same bits). Sub-tables missing from the cache are reduced from one solve of every
// surface, never one solve per sub-table. Returns each sub-table's status (as resolve_table).
std::vector<std::string> resolve_leave_out_tables(const TableStudy& t, double ball_radius, double effective_modulus,
                                                  bool rebuild, bool quiet);

}  // namespace rollspec::stiffness
