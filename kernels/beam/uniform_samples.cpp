#include "kernels/beam/uniform_samples.hpp"

#include <stdexcept>

namespace rollspec::beam {

void UniformSamples::throw_bad_samples() {
  throw std::invalid_argument("UniformSamples: need >= 2 samples and step > 0");
}

void UniformSamples::throw_out_of_range() {
  throw std::out_of_range("UniformSamples: position outside the sampled range");
}

}  // namespace rollspec::beam
