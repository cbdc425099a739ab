#pragma once
// Line PSD of an isotropic rough surface as a circular Hertz contact of radius a sees it
// (kernels/texture/README.md §11, Eq. 36-40; issue 19, `[contact] filter = iso2d`).
//
// To first order in the roughness, the force of a contact at fixed approach weights the height
// under it with the flat-punch pressure per unit approach, normalised (Eq. 36):
//   w(r) = 1 / (2 pi a sqrt(a^2 - r^2)),  r < a,   int w d^2x = 1,
// whose 2D Fourier transform is (Eq. 37)
//   w^(q) = sin(q a) / (q a).
// Uniform corrugation h(x) sees w^(k_x, 0) = sin(k a)/(k a), the 1D patch filter B35. An isotropic
// surface with 2D PSD C_iso(q) (D-5, Eq. 18-20) gives along the path the one-sided line PSD
//   G_eq(k) = pi^-2 int_0^inf C_iso(sqrt(k^2 + y^2)) [sin(q a)/(q a)]^2 dy,   q = sqrt(k^2 + y^2)  (Eq. 38)
// which for a -> 0 is the forward projection Eq. 18 (= G(k)).
//
// C_iso is taken in the form IsotropicPsd builds (Eq. 20): a smooth part S(q) on q < q_e plus the
// end jump 2 pi J / sqrt(q_e^2 - q^2) of a line PSD that drops by J at q_e. Eq. 38 is then split
// (Eq. 39): the smooth part by Gauss-Legendre panels in y (geometric from y = k, panel ends at S's
// kinks, at most half an oscillation of the weight per panel), the jump part by y = Y sin(theta),
// Y = sqrt(q_e^2 - k^2), which removes its inverse square root:
//   G_eq = pi^-2 int_0^Y S(q) W dy + (2 J / pi) int_0^{pi/2} W(a q(theta)) dtheta,  W(s) = (sin s / s)^2.
// No tail beyond q_e: C_iso is zero there by construction (a PSD without an upper end is
// truncated where IsotropicPsd is told to, see contact_filtered_psd).
#include <cstddef>
#include <functional>
#include <vector>

#include "kernels/texture/isotropic_psd.hpp"
#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

// C_iso(q) = smooth(q) + 2 pi jump / sqrt(q_end^2 - q^2) for q < q_end, 0 above (Eq. 20).
struct IsotropicSpectrum {
  std::function<double(double)> smooth;  // S(q), m^4
  double q_end = 0.0;                    // q_e, rad/m (finite)
  double jump = 0.0;                     // J, m^3
  std::vector<double> kinks;             // q where S or S' is not smooth (panel ends)
};

// The spectrum IsotropicPsd represents; kinks: the line PSD's breakpoints.
IsotropicSpectrum isotropic_spectrum(const IsotropicPsd& c, const std::vector<double>& kinks);

// sin(s)/s with its limit 1 at s = 0 (Eq. 37).
double flat_punch_transfer(double s);

// Eq. 38 at one k >= 0 by Eq. 39 (Gauss-Legendre panels); a >= 0 (a = 0: Eq. 18).
double contact_filtered_line_psd(const IsotropicSpectrum& c, double a, double k);

// Plain reference of Eq. 38: trapezoid rule on `intervals` uniform intervals of y in [0, Y] for
// the smooth part, midpoint rule on `intervals` intervals of theta for the jump part.
double contact_filtered_line_psd_reference(const IsotropicSpectrum& c, double a, double k, std::size_t intervals);

// The engine's step: line PSD g -> C_iso (Eq. 19-20, q from k_min / 2) -> G_eq (Eq. 38) on a log grid of
// `points_per_decade` from k_min to min(q_e, k_max), steps at most pi / (64 a), plus g's breakpoints,
// log-log interpolated (Eq. 40), zero outside. q_cap: where a PSD without upper end is cut
// (IsotropicPsd); k_max: the largest k anyone asks for (a line's Nyquist wavenumber: the surface
// above it still counts, through y). Throws std::invalid_argument for a <= 0, k_min <= 0 or k_max <= k_min.
Psd contact_filtered_psd(const Psd& g, double a, double k_min, double q_cap, double k_max,
                         std::size_t points_per_decade = 200);

// Eq. 38 of g at the given wavenumbers (all > 0) directly, without the table: for a few points.
std::vector<double> contact_filtered_psd_at(const Psd& g, double a, const std::vector<double>& k, double q_cap);

}  // namespace rollspec::texture
