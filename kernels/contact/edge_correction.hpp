#pragma once
// Sub-cell contact edge for the frozen-set stiffness (README Eq. 13–15).
//
// The frozen-set k of README Eq. 11 is the exact derivative of the discrete P(w), which changes
// set whenever a cell centre is crossed by the contact edge: along w it is a staircase around the
// continuum stiffness (Hertz, 32 cells per radius: up to 3.9e-3 off 2E*a). Its smooth part is the
// stiffness of the contact region whose edge passes each cell centre at the approach where that
// cell switches. This routine estimates, for every cell on the elastic/open boundary, the fraction
// θ of the cell inside that region (README Eq. 13–14) and the marginal stiffness per unit area m
// of the local edge (README Eq. 15), and returns δk = ΔA Σ m_b (θ_b − χ_b), χ_b = 1 for contact
// cells: k = k_frozen + δk. Local, O(N) apart from the one half-space product the caller supplies.
#include <vector>

#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

struct EdgeCorrection {
  double delta_k = 0.0;        // δk (N/m), README Eq. 15
  std::size_t band_cells = 0;  // boundary cells on the elastic/open edge
  std::size_t used_cells = 0;  // of those, cells with a usable θ and m (the rest keep θ = χ)
};

// p: contact pressure (Pa); dp: frozen-set rate dp/dw (README Eq. 11, Pa/m); gap: g = s − w + C p
// (m); rate_u: C dp (dimensionless, the displacement rate on every cell); hardness H (may be +inf).
// All arrays on `grid`, x-fastest. Plain loops (no FFT), on the box of the elastic cells grown by
// two cells (all that the sums read); `edge_correction_reference` runs them on the whole grid (the
// same bits).
EdgeCorrection edge_correction(const Grid& grid, double e_star, double approach, const std::vector<double>& p,
                               const std::vector<double>& dp, const std::vector<double>& gap,
                               const std::vector<double>& rate_u, double hardness);
EdgeCorrection edge_correction_reference(const Grid& grid, double e_star, double approach, const std::vector<double>& p,
                                         const std::vector<double>& dp, const std::vector<double>& gap,
                                         const std::vector<double>& rate_u, double hardness);

// Fraction of a dx × dy cell on the inner side of a straight edge with outward unit normal
// (nx, ny) that lies at signed distance t beyond the cell centre (t > 0: centre inside). README Eq. 14.
double cell_fraction_inside(double t, double nx, double ny, double dx, double dy);

}  // namespace rollspec::contact
