#pragma once
// Test support: the Welch settings the spectral tests vary (sample rate, segment, overlap), with the window and the
// detrending at their defaults.
#include <cstddef>

#include "kernels/spectral/welch.hpp"

namespace rollspec::spectral::testing {

inline WelchConfig welch_config(double sample_rate, std::size_t segment, std::size_t overlap) {
  WelchConfig c;
  c.sample_rate = sample_rate;
  c.segment = segment;
  c.overlap = overlap;
  return c;
}

}  // namespace rollspec::spectral::testing
