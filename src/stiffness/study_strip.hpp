#pragma once
// One rough strip of the study's surface: the height field a contact stage slides the ball along
// (blocked force, equivalent roughness, path table). Strip `index` is the surface realisation
// keyed ([stiffness] table_seed, index) on the tables' own Philox surface streams, so every stage that asks for strip 0
// of the same grid sees the same heights.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/texture/surface.hpp"
#include "src/stiffness/table_study.hpp"

namespace rollspec::stiffness {

struct StripGrid {
  std::size_t nx = 0, ny = 0;     // cells along and across the path
  double cell = 0.0;              // dx = dy (m)
  bool allow_truncation = false;  // a derived cell may drop roughness shorter than two cells
};

// Heights of strip `index` (x fastest, centred as contact::Grid). Bad texture or grid: config_error
// naming [surface] spacing.
texture::Surface study_strip(const TableStudy& ts, const StripGrid& g, std::uint64_t index);

// The part of a contact stage's input text (its cache hash) that fixes the strip's heights and the
// solver settings: [stiffness] hardness, tolerance, max_iterations, table_seed, the strip grid's width
// and cell, the surface and texture keys and a fingerprint of the texture's input files.
std::string strip_inputs_text(const TableStudy& ts, const StripGrid& g);

// The head of that input text: the contact kernel's version and the ball (radius, E*, load, shape).
std::string ball_inputs_text(const TableStudy& ts, double radius, double effective_modulus, double load);

// A one-sided path PSD tabulated at wavenumbers k_0 = 0 < k_1 < ... (a strip stage's Welch PSD) at k:
// log-log between bins (linear where a bin is 0), the first bin's level below it, 0 above the last.
double path_psd_at(const std::vector<double>& wavenumbers, const std::vector<double>& psd, double k);

// contact BF-9c for a strip table checked as it ran (BF-9, ER-8): the estimated rms error (dB) of its path
// PSD (per rad/m, `psd_wavenumber` from a half-overlapping Hann Welch plan at `step` m) averaged over the
// wavenumbers [lower, upper] (rad/m), the check residuals taken as a white error about their mean (a constant
// offset leaves the fluctuation's PSD alone); `samples`: the path samples behind the PSD (its degrees of
// freedom); a band below bin `first_bin` takes that bin's. NaN with fewer than 2 residuals or beyond the bins.
double checked_band_error_db(const std::vector<double>& residuals, double step, std::size_t samples,
                             const std::vector<double>& psd_wavenumber, const std::vector<double>& psd, double lower,
                             double upper, std::size_t first_bin);

// |P - W| <= tolerance * W of the equivalent-roughness solves (ER-1) for solves stopped at the
// study's complementarity error eps (README Eq. 9): the force of such a solve is known to about
// k eps g_ref ~ 1.5 eps (g_ref / delta) W, several eps on a rough strip (g_ref, the largest
// interference, exceeds delta by the peaks), so 100 eps (h_eq to ~1e-6 delta_H), never below 1e-10.
double strip_load_tolerance(const contact::SolverOptions& options);

}  // namespace rollspec::stiffness
