#pragma once
// The PSD the line and surface generators take from measured profiles (README Eq. 44-45).
//
// Resolved band, k >= k_r = (j_r - 1/2) dk: the band-averaged estimate of Eq. 33-35 and 41, at the
// periodogram's own level (Eq. 43). Below it the unresolved variance V_u = max(0, V - V_r) (Eq. 44),
// kept apart from the resolved octaves:
//
//   G(k) = c                               3/2 dk <= k < k_r
//   G(k) = c + (V_u - c (j_r - 1) dk) / dk   dk/2 <= k < 3/2 dk                              (Eq. 45)
//   c = min(G_r, V_u / ((j_r - 1) dk)),   G_r = the table's value at k_r
//
// i.e. the resolved level continued flat down to the scan's longest wave (a flat spectrum's bins
// below j_r hold about that), and whatever more the scan holds given to its longest cell, the
// wavelengths 2L/3 .. 2L of a scan of length L = N dx: the window and the trend removal cannot say
// where below k_r that variance is, and any of it placed next to k_r would leak into the resolved
// octaves of a line analysed like the scan.
//
// Outside [dk/2, pi/dx] the extension decides: error (std::domain_error naming the measured range),
// zero, or constant and power_law, which continue the lowest cell's level below (a flat cell has no
// slope) and the table's rule above. cell_average is set (Eq. 14b): every synthesis grid keeps the
// PSD's power in its cells.
#include "kernels/texture/profile_psd.hpp"
#include "kernels/texture/psd.hpp"
#include "kernels/texture/psd_smoothing.hpp"
#include "kernels/texture/tabulated_psd.hpp"

namespace rollspec::texture {

// Eq. 45's pieces below the resolved band, rad/m and m^3.
struct UnresolvedCells {
  double k_low = 0.0;       // dk/2: the longest cell's lower edge, the lowest wavenumber the PSD covers
  double k_cell = 0.0;      // 3/2 dk: its upper edge
  double k_resolved = 0.0;  // k_r = (j_r - 1/2) dk
  double level = 0.0;       // c
  double cell_level = 0.0;  // c plus the rest of V_u spread over the longest cell
};

// Eq. 45 for an estimate whose resolved table starts at G_r = resolved_level.
UnresolvedCells unresolved_cells(const EstimatedPsd& estimate, double resolved_level);

// Eq. 44-45 with the table of Eq. 33-35, 41 over bins first_resolved .. N/2 (bands.first_bin is
// taken from the estimate). Throws std::invalid_argument if fewer than 2 bands fit.
Psd measured_line_psd(const EstimatedPsd& estimate, Extension extension, const PsdBands& bands = {});

}  // namespace rollspec::texture
