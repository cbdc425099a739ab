#pragma once
// ISO 3095:2013 limit spectrum of rail roughness for the reference track (clause 6.2; the
// one-third-octave wavelength table of the standard, levels L in dB re 1 um; cross-checked with
// the table as tabulated in public rail-acoustics code). README Eq. 10-11:
//
//   band rms roughness   r_b = 1e-6 m * 10^{L_b / 20}                              (Eq. 10)
//   band PSD             G_b = r_b^2 / (k_b,upper - k_b,lower)   at the band centre k_b   (Eq. 11)
//
// The bands are IEC 61260-1 base-ten third octaves in spatial frequency n = 1/lambda: exact
// centre n_b = 10^{x/10} cycles/m for the nominal wavelength, edges n_b 10^{+-1/20}. The
// returned table interpolates G_b log-log between band centres.
#include <vector>

#include "kernels/texture/tabulated_psd.hpp"

namespace rollspec::texture {

struct RoughnessBand {
  double wavelength_nominal;  // m, as printed in the standard
  double level_db;            // dB re 1 um
  double k_centre;            // rad/m, exact base-ten centre
  double k_lower, k_upper;    // rad/m, band edges
  double psd;                 // G_b, m^3 (Eq. 11)
};

// The 22 bands from lambda = 0.4 m to 3.15 mm.
std::vector<RoughnessBand> iso3095_rail_roughness_limit();

// The limit as a table PSD, log-log between band centres (extension as given).
TabulatedPsd iso3095_rail_psd(Extension extension = Extension::error);

}  // namespace rollspec::texture
