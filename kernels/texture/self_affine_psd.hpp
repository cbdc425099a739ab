#pragma once
// Self-affine line PSD with roll-off and cut-offs (Jacobs, Junge & Pastewka 2017; README Eq. 6-8):
//
//   G(k) = C                          k_l <= k <  k_r   (roll-off plateau)
//   G(k) = C (k / k_r)^{-(1 + 2H)}    k_r <= k <= k_s   (self-affine, Hurst exponent H)
//   G(k) = 0                          otherwise          (long / short cut-offs)
//
// C is set from the exact integrals, rho = k_s / k_r, a = 1 + 2H:
//   h_rms^2 = C [ (k_r - k_l) + k_r (1 - rho^{1-a}) / (a - 1) ]                       (Eq. 7)
//   s_rms^2 = C [ (k_r^3 - k_l^3) / 3 + k_r^3 (rho^{3-a} - 1) / (3 - a) ]  (k_r^3 ln rho at a = 3)  (Eq. 8)
#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

enum class RmsTarget { height, slope };

struct SelfAffineSpec {
  double hurst = 0.8;      // H in (0, 1]
  double k_long = 0.0;     // k_l, rad/m: long-wavelength cut-off (0: none below the plateau)
  double k_rolloff = 0.0;  // k_r, rad/m: k_l <= k_r (k_r = k_l: no plateau); must be > 0
  double k_short = 0.0;    // k_s, rad/m: short-wavelength cut-off, > k_r
  RmsTarget target = RmsTarget::height;
  double rms = 0.0;  // m (height) or dimensionless (slope), > 0
};

struct SelfAffinePsd {
  SelfAffineSpec spec;
  double c = 0.0;  // plateau level C, m^3

  explicit SelfAffinePsd(const SelfAffineSpec& s);  // validates, computes C (Eq. 7 or 8)
  double operator()(double k) const;
  double rms_height() const;  // Eq. 7 with this C
  double rms_slope() const;   // Eq. 8 with this C
  Psd to_psd() const;
};

}  // namespace rollspec::texture
