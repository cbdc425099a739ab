#pragma once
// The path table's own estimated error at the answer (kernels/beam README B47): its static approach
// δ_W(ξ), as the run interpolates it (B44, B45 or B45b, thinned as the run reads it), against a cold
// load-controlled solve at the table's check points, midway between positions. δ_W is the path law's
// equivalent roughness (it enters the dynamics as h_eq of ER-2 does the point law's), so the residuals
// r_j = δ_W,solve(ξ_j) − δ_W,table(ξ_j) reach the band levels of δ_W's PSD by BF-9c, as ER-8's do.
#include <cstddef>
#include <vector>

#include "kernels/beam/path_contact_table.hpp"

namespace rollspec::scenes {

struct PathTableCheck {
  std::vector<double> residual;        // r_j (m)
  double step = 0.0;                   // the table's position spacing (m)
  std::size_t samples = 0;             // positions behind the PSD
  std::vector<double> psd_wavenumber;  // rad/m
  std::vector<double> psd;             // one-sided PSD of δ_W(ξ_k) over the tabulated positions (m² m/rad)
  // BF-9c: the rms error (dB) of δ_W's PSD averaged over [lower, upper] (rad/m); NaN beyond the bins.
  double band_error_db(double lower, double upper, std::size_t first_bin) const;
};

// `static_approach`: δ_W(ξ_k) of the table at its positions (beam::path_static_approaches); `check_position`:
// ξ_j (m, the table's path coordinate), `check_approach`: δ_W there by the solver (m). An empty PathTableCheck
// (no residuals) where the table has no checks or fewer than 8 positions.
PathTableCheck path_table_check(const beam::PathContactTable& table, double load,
                                const std::vector<double>& static_approach, const std::vector<double>& check_position,
                                const std::vector<double>& check_approach);

}  // namespace rollspec::scenes
