#pragma once
// Unit conversions of one-sided PSDs (kernels/README.md (conventions), D-2; kernels/texture/README.md Eq. 1-3).
//
//   wavenumber k [rad/m] = 2 pi n,  n = spatial frequency [cycles/m]
//   G_n(n) = 2 pi G_k(k)                         (same variance: G_n dn = G_k dk)     (Eq. 1)
//   time at rolling speed v: f = v n,  G_t(f) = G_n(n) / v = 2 pi G_k(k) / v        (Eq. 2, D-2)
//   a line texture h(x_i), x_i = i dx, becomes the time signal h(t_i), t_i = x_i / v (Eq. 3)
#include <cmath>

namespace rollspec::texture {

inline double spatial_frequency_from_wavenumber(double k) { return k / (2.0 * M_PI); }
inline double wavenumber_from_spatial_frequency(double n) { return 2.0 * M_PI * n; }
inline double psd_n_from_psd_k(double g_k) { return 2.0 * M_PI * g_k; }  // m^3 per rad/m -> m^3 per cycle/m
inline double psd_k_from_psd_n(double g_n) { return g_n / (2.0 * M_PI); }

// Space -> time at speed v (m/s), Eq. 2.
inline double frequency_from_wavenumber(double k, double speed) { return speed * k / (2.0 * M_PI); }
inline double wavenumber_from_frequency(double f, double speed) { return 2.0 * M_PI * f / speed; }
inline double psd_time_from_psd_k(double g_k, double speed) { return 2.0 * M_PI * g_k / speed; }
inline double time_step_from_spacing(double dx, double speed) { return dx / speed; }  // Eq. 3

}  // namespace rollspec::texture
