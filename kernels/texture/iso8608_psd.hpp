#pragma once
// ISO 8608 road roughness classes (README Eq. 9):
//
//   G_d(n) = G_d(n_0) (n / n_0)^{-w},  n_0 = 0.1 cycles/m,  w = 2 (waviness)
//   G_d(n_0) = 16e-6 m^3 * 4^c  for class c = A(0), B(1), ..., H(7)  (geometric class means:
//   A 16e-6, B 64e-6, C 256e-6, D 1024e-6, E 4096e-6, F 16384e-6, G 65536e-6, H 262144e-6 m^3)
//
// G_d is per cycle/m; the kernel's G(k) = G_d(k / 2 pi) / (2 pi) (Eq. 1). The standard states
// the classes over 0.011 <= n <= 2.83 cycles/m; outside [n_min, n_max] the PSD is zero.
#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

struct Iso8608Spec {
  char road_class = 'A';  // 'A'..'H'
  double waviness = 2.0;  // w
  double n_min = 0.011;   // cycles/m
  double n_max = 2.83;    // cycles/m
};

double iso8608_reference_level(char road_class);  // G_d(n_0), m^3; throws for a class outside A..H
Psd iso8608_psd(const Iso8608Spec& spec);

}  // namespace rollspec::texture
