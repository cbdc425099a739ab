#include "kernels/spectral/tabulated_math.hpp"

#include <cmath>

namespace rollspec::spectral {

namespace {
// Table entries from long-double libm, rounded once to double.
TabulatedMath build() {
  TabulatedMath t{};
  for (int i = 0; i < 256; ++i) {
    // Centres with 10 significant bits, so m - c is exact; the top bin's centre is 2, so that
    // u -> 1 (e = -1, m -> 2) gives -ln u = -ln(1 + r) with no cancellation against ln(c / 2).
    const double c = i == 255 ? 2.0 : 1.0 + (i + 0.5) / 256.0;
    t.log_bin[i].centre = c;
    t.log_bin[i].inverse = 1.0 / c;
    t.log_bin[i].half_centre = static_cast<double>(std::log(static_cast<long double>(c) / 2.0L));
  }
  const long double two_pi = 6.283185307179586476925286766559005768L;
  // First quadrant from libm, the others by exact symmetry (so sin(pi) is 0, not 1e-19).
  for (int k = 0; k < 1024; ++k) {
    const int q = k / 256, r = k % 256;
    const long double a = two_pi * static_cast<long double>(r) / 1024.0L;
    const auto c = static_cast<double>(std::cos(a)), s = static_cast<double>(std::sin(a));
    const double cq[4] = {c, -s, -c, s}, sq[4] = {s, c, -s, -c};
    t.cos_sin[2 * k] = cq[q];
    t.cos_sin[2 * k + 1] = sq[q];
  }
  return t;
}
}  // namespace

const TabulatedMath& tabulated_math() {
  static const TabulatedMath t = build();
  return t;
}

}  // namespace rollspec::spectral
