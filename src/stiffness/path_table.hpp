#pragma once
// The path table stage of `[contact] law = path` (issue 19 item 2; kernels/beam README B41–B46):
// P(δ, ξ) of strip 0 of the study's surface (study_strip, the strip the blocked-force and
// equivalent-roughness stages slide over), at J approaches and every path position the ball
// passes in the run. A CachedTable like the blocked-force table (input hash, schema, kernel
// version, data checksum), file type "rollspec-path-table".
//
// Grid: the cell, the contact radius a and the texture rms of blocked_force_geometry (the same
// derivation). From them
//   step   ≤ a/2 with B45b's cubic interpolation in ξ, ≤ a/4 with B45's linear (whole cells;
//          [path_table] step overrides);
//   window holds every cell that can touch at the table's largest approach, max δ_c + 3 δ_H (B43):
//          half-width sqrt(2 R (3.3 δ_H + 14 σ)) (the strip's highest point and deepest valley
//          within 7 σ each), never less than 2.6 a;
//   width  the window, or [surface] ny;
//   length the ball's path in the run, (end − start) + one step, plus the window, or
//          [path_table] strip_length (refused when shorter than that).
#include <cstddef>
#include <string>
#include <vector>

#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/stiffness/cached_table.hpp"
#include "src/stiffness/table_study.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/path_table_section.hpp"

namespace rollspec::stiffness {

constexpr const char* kPathTableFileType = "rollspec-path-table";

// B47: one check per this many position intervals (about 1 % of the table's solves on the seed 002 rig).
constexpr std::size_t kPathCheckStride = 16;

extern const TableKind kPathTableKind;

struct PathTableGeometry {
  BlockedForceGeometry base;       // cell, contact radius, rms (the blocked-force derivation)
  std::size_t nx = 0, ny = 0;      // strip (cells)
  std::size_t window = 0;          // solver window (cells, square)
  std::size_t step = 0;            // path step (cells)
  std::size_t positions = 0;       // path positions
  std::size_t approaches = 0;      // J
  bool ladder = false;             // B43b: each position's own approaches above its first contact
  double path_length = 0.0;        // the ball's path in the run (m)
  double solve_seconds = 0.0;      // CPU seconds of one plane-ladder solve (B43, contact_box_work)
  double estimated_seconds = 0.0;  // CPU seconds of the build (rough)
  int threads = 1;                 // threads the build uses (rows in parallel)
  std::string describe() const;
};

struct PathTableData : TableData {
  std::vector<double> position;       // ξ_k − ξ_0 (m, path coordinate from the traverse's start)
  std::vector<double> approach;       // δ_j (m); B43b: the offsets s_j above δ_c(ξ_k)
  std::vector<double> first_contact;  // δ_c(ξ_k) (m)
  std::vector<double> force;          // P(δ_j, ξ_k) (N) at [j · N + k]; B43b: NaN above rows[k]
  std::vector<double> rows;           // B43b: rows solved at each position; empty: every row (B43)
  // B47: the table's checks, midway between positions in every kPathCheckStride-th interval: ξ (m, path
  // coordinate) and δ_W there by a load-controlled solve (m, from the mean plane). Empty: a table without checks.
  std::vector<double> check_position;
  std::vector<double> check_approach;
  double load = 0.0;
  void load_from(const io::Hdf5Reader& r) override;
  void save_to(io::Hdf5Writer& w) const override;
  std::string checksum() const override;
};

PathTableGeometry path_table_geometry(const study::PathTableSection& path_table,
                                      const study::BlockedForceSection& blocked_force,
                                      const study::StripSurfaceSection& surface, const texture::Psd& psd, double radius,
                                      double effective_modulus, double load, double path_length);

CachedTable path_cached_table(const TableStudy& ts, const PathTableGeometry& g, double radius, double effective_modulus,
                              double load);

PathTableData build_path_table(const TableStudy& ts, const PathTableGeometry& g, double radius,
                               double effective_modulus, double load, bool quiet);

}  // namespace rollspec::stiffness
