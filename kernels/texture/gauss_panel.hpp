#pragma once
// 8-point Gauss-Legendre quadrature of f over one panel [lo, hi] (exact for polynomials of degree
// 15): the smooth pieces of the contact filter's integrals (Eq. 39) and the harmonics' cell powers
// (Eq. 14b).
namespace rollspec::texture {

inline constexpr double kGaussPanelX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                           0.9602898564975363};
inline constexpr double kGaussPanelW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                           0.1012285362903763};

template <class F>
double gauss_panel(double lo, double hi, F f) {
  const double h = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  double acc = 0.0;
  for (int i = 0; i < 4; ++i) acc += kGaussPanelW[i] * (f(mid - h * kGaussPanelX[i]) + f(mid + h * kGaussPanelX[i]));
  return acc * h;
}

}  // namespace rollspec::texture
