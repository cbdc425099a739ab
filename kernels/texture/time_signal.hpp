#pragma once
// A line texture seen by a contact rolling at constant speed v (kernels/README.md D-2; README Eq. 2-3):
// h(t_i) = h(x_i) with t_i = x_i / v, so the samples are unchanged and dt = dx / v; the
// one-sided PSD in time is G_t(f) = G_n(f / v) / v = 2 pi G_k(2 pi f / v) / v.
#include <functional>
#include <vector>

#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

struct TimeSignal {
  double dt = 0.0;             // s
  std::vector<double> values;  // m
};

TimeSignal line_to_time_signal(std::vector<double> heights, double spacing, double speed);

// G_t(f), m^2/Hz, f in Hz.
std::function<double(double)> time_psd(const Psd& psd, double speed);

}  // namespace rollspec::texture
