#pragma once
// Exact static flexibility (Green's function) of a uniform Euler–Bernoulli beam of length L,
// README Eq. (B7)–(B8): deflection at x (positive along the load) per unit point load at a,
// b = L - a, x <= a (x > a by the mirror G(x, a) = G(L - x, L - a)):
//   clamped–clamped:   G = b^2 x^2 (3 a L - 3 a x - b x) / (6 EI L^3),  G(a, a) = a^3 b^3 / (3 EI L^3)
//   simply supported:  G = b x (L^2 - b^2 - x^2) / (6 EI L),             G(a, a) = a^2 b^2 / (3 EI L)
#include "kernels/beam/beam_modes.hpp"

namespace rollspec::beam {

double static_flexibility(Support support, double length, double bending_stiffness, double x, double a);

}  // namespace rollspec::beam
