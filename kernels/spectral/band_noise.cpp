#include "kernels/spectral/band_noise.hpp"

#include <cmath>
#include <stdexcept>

namespace rollspec::spectral {

BandNoise band_noise(double model_power, double noise_power, double measured_dof, double noise_dof) {
  if (!(model_power > 0.0) || !std::isfinite(model_power) || !(noise_power >= 0.0) || !std::isfinite(noise_power))
    throw std::invalid_argument("band noise: needs a model power > 0 and a noise power >= 0, both finite");
  if (!(measured_dof >= 0.0) || !(noise_dof >= 0.0))
    throw std::invalid_argument("band noise: degrees of freedom must be >= 0 (0: unknown)");
  BandNoise n;
  const double r = noise_power / model_power, a = 1.0 / (1.0 + r);
  n.shift = std::log1p(r);
  n.signal_share = a * a;
  // 1 - a^2 = r (2 + r) a^2 and 1 - a = r a, written so that a small r loses no digits.
  if (measured_dof > 0.0) n.measured = std::log1p(2.0 * r * (2.0 + r) * a * a / measured_dof);
  if (noise_dof > 0.0) n.estimate = std::log1p(2.0 * r * r * a * a / noise_dof);
  return n;
}

}  // namespace rollspec::spectral
