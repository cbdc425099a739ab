#pragma once
// Data windows for spectral estimation.
#include <cstddef>
#include <string>
#include <vector>

namespace rollspec::spectral {

enum class Window { hann, rectangular };

// Periodic ("DFT-even") window of length n, as scipy.signal.get_window(..., fftbins=True):
// Hann w_i = 0.5 - 0.5 cos(2 pi i / n). Periodic windows make 50 % overlapped Hann sum to a constant.
std::vector<double> make_window(Window kind, std::size_t n);

// Equivalent noise bandwidth in bins: n sum(w^2) / (sum w)^2 (Hann: 1.5, rectangular: 1).
double equivalent_noise_bandwidth_bins(const std::vector<double>& w);

}  // namespace rollspec::spectral
