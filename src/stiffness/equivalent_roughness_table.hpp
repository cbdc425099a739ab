#pragma once
// Equivalent-roughness table of `[contact] filter = solver` (issue 19; kernels/contact README
// ER-1..ER-6): on `[equivalent_roughness] strips` rough strips of the study's surface (strip s =
// study_strip(..., s), the Philox surface realisation s), h_eq(xi) = delta_smooth - delta_eq(xi) at
// the ball's weight along the blocked-force grid (BlockedForceGeometry: cell, window, step,
// positions), and the one-sided PSD of h_eq along the path (per rad/m) averaged over the strips,
// from which the ball-on-beam scene synthesises its line textures. A CachedTable like the
// blocked-force table (input hash, schema, kernel version, data checksum).
#include <string>
#include <vector>

#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/stiffness/cached_table.hpp"
#include "src/stiffness/table_study.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::stiffness {

constexpr const char* kEquivalentRoughnessFileType = "rollspec-equivalent-roughness";

extern const TableKind kEquivalentRoughnessTableKind;

struct EquivalentRoughnessTable : TableData {
  std::vector<double> position;             // m along the strip (the same for every strip)
  std::vector<double> height;               // h_eq (m), strips x positions (ER-2)
  std::vector<double> psd_wavenumber, psd;  // rad/m, m^3 (one-sided PSD of h_eq - mean, strip mean)
  std::vector<double> stiffness;            // k_eq (N/m) at delta_eq, strips x positions (ER-7)
  double smooth_approach = 0.0, smooth_stiffness = 0.0, load = 0.0, strips = 0.0;
  // contact ER-8 (answer_tolerance > 0; empty / 0 for the reference): the solves' tolerance, the positions
  // solved again to the full tolerance (m, every strip's in strip order) and h_eq there minus the tabulated
  // h_eq (m): the table's error measured as it ran.
  double answer_tolerance = 0.0;
  std::vector<double> check_position, check_residual;
  // BF-9c on ER-8's residuals: the estimated rms error (dB) of the h_eq PSD averaged over the wavenumbers
  // [lower, upper] (rad/m); a band below bin `first_bin` takes that bin's; NaN without checks (the
  // reference table) or beyond the PSD's bins.
  double band_error_db(double lower, double upper, std::size_t first_bin) const;
  // rho of ER-7: the strips' mean k_eq over the flat strip's k at the weight (same discretisation).
  double stiffness_ratio() const;
  // G of h_eq at wavenumber k, as BlockedForceTable::psd_at: log-log between bins, the first bin's
  // level below them, zero above the path's Nyquist wavenumber.
  double psd_at(double k) const;

  void load_from(const io::Hdf5Reader& r) override;
  void save_to(io::Hdf5Writer& w) const override;
  std::string checksum() const override;
};

// Estimated build time on one core (s), for the plan: strips x positions force-controlled solves.
double equivalent_roughness_seconds(const TableStudy& ts, const BlockedForceGeometry& g);
// The same model's time of probe_equivalent_roughness (s): `plan` probes unasked only when it is at
// most kQuickProbeSeconds (a few seconds against a build about thirty times longer); `plan --probe`
// always.
double equivalent_roughness_probe_seconds(const TableStudy& ts, const BlockedForceGeometry& g);
constexpr double kQuickProbeSeconds = 5.0;

// `plan`: the build's CPU time (s) measured rather than modelled: the first chunk of strip 0
// (64 positions, with the flat strip's solve) solved as the build solves it, on one thread, scaled to
// every position of every strip. The solves' cost follows the listed cells' box, which the texture
// sets and the window model above cannot see (contact README Eq. 17).
struct TableProbe {
  double seconds = 0.0;        // estimated CPU seconds of the whole build
  double probe_seconds = 0.0;  // CPU seconds the probe took
  std::size_t positions = 0;   // positions the probe solved
  int threads = 1;             // threads the build would use (its chunks share them)
};
TableProbe probe_equivalent_roughness(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                      double effective_modulus, double load);

// "2 strips of 400 x 64 cells, ... positions, ...; build about ... s" for the plan and the log.
std::string equivalent_roughness_describe(const TableStudy& ts, const BlockedForceGeometry& g);

CachedTable equivalent_roughness_cached_table(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                              double effective_modulus, double load);

// The table without strip `skip` (its h_eq PSD and stiffness from the other strips; no new solve):
// the jackknife's sub-table ([equivalent_roughness] leave_out, kernels/spectral D-30); `g`: the geometry
// the table was made on (its step and Welch segment).
EquivalentRoughnessTable leave_out_strip(const EquivalentRoughnessTable& t, std::size_t skip,
                                         const BlockedForceGeometry& g);

EquivalentRoughnessTable build_equivalent_roughness(const TableStudy& ts, const BlockedForceGeometry& g, double radius,
                                                    double effective_modulus, double load, bool quiet);

}  // namespace rollspec::stiffness
