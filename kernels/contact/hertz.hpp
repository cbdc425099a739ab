#pragma once
// Hertz's closed forms for a smooth sphere of radius R pressed onto an elastic half-space, both bodies'
// elasticity in the effective modulus E* (D-6, effective_modulus in geometry.hpp); Johnson, Contact
// Mechanics (1985) §4.2, Eq. (4.22)–(4.24) and the check of kernels/README.md (contact):
//
//   a = (3 P R / 4 E*)^{1/3} = sqrt(R δ),   δ = (3 P / (4 E* sqrt(R)))^{2/3},   P = (4/3) E* sqrt(R) δ^{3/2},
//   p0 = 3 P / (2 π a²) = 2 E* a / (π R),   k = dP/dδ = 2 E* a
//
// with P the load, δ the approach (compression), a the contact radius, p0 the peak pressure and k the
// contact stiffness. The engine, the contact laws and the tests read them here; each function's name
// says whether it takes the load or the approach. Each is written as the engine has always evaluated
// it (the same operations in the same order), so moving them here changed no result's bits.
#include <algorithm>
#include <cmath>

namespace rollspec::contact::hertz {

// K in P = K δ^{3/2} (the Hertz law B17 caches it).
inline double force_coefficient(double radius, double e_star) { return 4.0 / 3.0 * e_star * std::sqrt(radius); }

// P(δ); no force without contact (δ <= 0).
inline double force_at_approach(double radius, double e_star, double approach) {
  return approach > 0.0 ? force_coefficient(radius, e_star) * approach * std::sqrt(approach) : 0.0;
}

// δ(P), P >= 0 (Johnson 4.23).
inline double approach_at_load(double radius, double e_star, double load) {
  return std::pow(3.0 * load / (4.0 * e_star * std::sqrt(radius)), 2.0 / 3.0);
}

// a(P), P >= 0 (Johnson 4.22).
inline double contact_radius_at_load(double radius, double e_star, double load) {
  return std::cbrt(3.0 * load * radius / (4.0 * e_star));
}

// a(δ) = sqrt(R δ); 0 without contact (δ <= 0). Also the contact-patch half-width (B35, B38).
inline double contact_radius_at_approach(double radius, double approach) {
  return std::sqrt(radius * std::max(approach, 0.0));
}

// k(δ) = dP/dδ = 2 E* a.
inline double stiffness_at_approach(double radius, double e_star, double approach) {
  return 2.0 * e_star * std::sqrt(radius * approach);
}

// p0(δ) = 2 E* a / (π R), the pressure at the centre (Johnson 4.24).
inline double peak_pressure_at_approach(double radius, double e_star, double approach) {
  return 2.0 * e_star * contact_radius_at_approach(radius, approach) / (M_PI * radius);
}

// p0(P) = 3 P / (2 π a²) (Johnson 4.24).
inline double peak_pressure_at_load(double radius, double e_star, double load) {
  const double a = contact_radius_at_load(radius, e_star, load);
  return 3.0 * load / (2.0 * M_PI * a * a);
}

}  // namespace rollspec::contact::hertz
