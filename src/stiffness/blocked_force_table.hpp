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
  std::string input_hash;  // of the CachedTable it came from
  // G of F0 at wavenumber k: log-log between the PSD bins, the first bin's level below them, zero
  // above the path's Nyquist wavenumber.
  double psd_at(double k) const;

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

}  // namespace rollspec::stiffness
