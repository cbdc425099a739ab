#pragma once
// Blocked-force tables for the linearised contact law (seed 002 §4.2; design D-11; kernels/contact
// blocked_force.hpp BF-1..BF-7): a smooth ball slid along one rough strip realisation at the fixed
// approach d0 whose mean force is the ball's weight. The table holds F0 and k along the path, d0,
// k0 = mean k, and the one-sided PSD of F0 along the path (per rad/m), from which the ball-on-beam
// scene synthesises F0(t) realisations at any speed (D-2: G_t(f) = 2 pi G_k(2 pi f / v) / v).
// A CachedTable like stiffness tables (input hash, schema, kernel version, data checksum).
#include <string>
#include <vector>

#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/stiffness/cached_table.hpp"
#include "src/stiffness/table_study.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::stiffness {

constexpr const char* kBlockedForceFileType = "rollspec-blocked-force";

extern const TableKind kBlockedForceTableKind;

struct BlockedForceTable : TableData {
  std::vector<double> position, force, stiffness;  // m, N, N/m along the path
  std::vector<double> psd_wavenumber, psd;         // rad/m, N^2 m / rad (one-sided PSD of F0 - mean)
  double approach = 0.0, k0 = 0.0, mean_force = 0.0, load = 0.0;
  // contact BF-8 only (answer_tolerance > 0; empty / 0 for the exhaustive search): each F0's estimated
  // error (N), the solves' tolerance and the first-order step onto the load (m).
  std::vector<double> force_error;
  double answer_tolerance = 0.0, load_step = 0.0;
  // contact BF-9 (answer_tolerance > 0): the positions solved again to the full tolerance (m), F0 there
  // minus the tabulated F0 (N), and k0's standard error (N/m, BF-9a): the table's error measured as it ran.
  std::vector<double> check_position, check_residual;
  double k0_error = 0.0;
  // G of F0 at wavenumber k: log-log between the PSD bins, the first bin's level below them, zero
  // above the path's Nyquist wavenumber.
  double psd_at(double k) const;
  // contact BF-9c: the estimated rms error (dB) of F0's PSD averaged over the wavenumbers [lower, upper]
  // (rad/m), the check residuals taken as a white error; a band below bin `first_bin` takes that bin's.
  // NaN without checks (the exhaustive table) or beyond the PSD's bins.
  double band_error_db(double lower, double upper, std::size_t first_bin) const;

  void load_from(const io::Hdf5Reader& r) override;
  void save_to(io::Hdf5Writer& w) const override;
  std::string checksum() const override;
};

// What a study asks for (no computation): canonical inputs, the grid `g` included, and
// <table_dir>/blocked-force-<hash>.h5.
CachedTable blocked_force_cached_table(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                       double effective_modulus, double load);

// Builds the table on the grid `g`: one strip realisation, the load search along the path, the PSD of F0.
BlockedForceTable build_blocked_force(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                      double effective_modulus, double load, bool quiet);

// The one-sided PSD of F0 - mean along the path into t.psd (per rad/m) from t.force: Welch on g's
// step and segment, over every segment (skip < 0) or over all but segment `skip` (D-30d).
void f0_psd(BlockedForceTable& t, const BlockedForceGeometry& g, long long skip);

// The Welch segments of F0 on grid g, the jackknife's units (kernels/spectral/README.md D-30d): half
// overlapping, so the jackknife's variance is scaled by 2 N / nu_Welch and has nu_Welch / 2 - 1
// degrees of freedom (D-16's equivalent dof of the Welch mean).
struct SegmentJackknife {
  std::size_t segments = 0;
  double variance_factor = 1.0, dof = 0.0;
};
SegmentJackknife f0_segments(const BlockedForceGeometry& g);

// The cached table with Welch segment `skip` left out of its F0 PSD ([blocked_force] leave_out, no
// new solve). k0, d0 and F0 along the path are the whole path's.
BlockedForceTable leave_out_segment(const BlockedForceTable& t, std::size_t skip, const BlockedForceGeometry& g);

}  // namespace rollspec::stiffness
