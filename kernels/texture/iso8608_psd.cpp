#include "kernels/texture/iso8608_psd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/texture/psd_units.hpp"

namespace rollspec::texture {

double iso8608_reference_level(char road_class) {
  if (road_class < 'A' || road_class > 'H')
    throw std::invalid_argument(std::string("ISO 8608 road class must be A..H, got '") + road_class + "'");
  return 16e-6 * std::pow(4.0, road_class - 'A');
}

Psd iso8608_psd(const Iso8608Spec& spec) {
  const double g0 = iso8608_reference_level(spec.road_class);
  if (!(spec.n_min > 0.0) || !(spec.n_max > spec.n_min) || !std::isfinite(spec.n_max))
    throw std::invalid_argument("ISO 8608 PSD: needs 0 < n_min < n_max (cycles/m)");
  if (!std::isfinite(spec.waviness)) throw std::invalid_argument("ISO 8608 PSD: waviness must be finite");
  constexpr double n0 = 0.1;
  const double w = spec.waviness, n_min = spec.n_min, n_max = spec.n_max;
  Psd p;
  p.density = [=](double k) {
    const double n = spatial_frequency_from_wavenumber(k);
    if (n < n_min || n > n_max) return 0.0;
    return psd_k_from_psd_n(g0 * std::pow(n / n0, -w));  // Eq. 9 then Eq. 1
  };
  p.support_min = wavenumber_from_spatial_frequency(n_min);
  p.support_max = wavenumber_from_spatial_frequency(n_max);
  p.breakpoints = {p.support_min, p.support_max};
  p.description = std::string("ISO 8608 class ") + spec.road_class;
  return p;
}

}  // namespace rollspec::texture
