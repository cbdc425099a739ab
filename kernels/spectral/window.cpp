#include "kernels/spectral/window.hpp"

#include <cmath>

namespace rollspec::spectral {

std::vector<double> make_window(Window kind, std::size_t n) {
  std::vector<double> w(n, 1.0);
  if (kind == Window::hann) {
    const double two_pi_over_n = 2.0 * M_PI / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) w[i] = 0.5 - 0.5 * std::cos(two_pi_over_n * static_cast<double>(i));
  }
  return w;
}

double equivalent_noise_bandwidth_bins(const std::vector<double>& w) {
  double s1 = 0.0, s2 = 0.0;
  for (double v : w) {
    s1 += v;
    s2 += v * v;
  }
  return static_cast<double>(w.size()) * s2 / (s1 * s1);
}

}  // namespace rollspec::spectral
