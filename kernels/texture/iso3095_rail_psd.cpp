#include "kernels/texture/iso3095_rail_psd.hpp"

#include <cmath>

namespace rollspec::texture {

namespace {
// ISO 3095:2013, limit of rail roughness (reference track): nominal wavelength (m), level (dB re 1 um).
struct Row {
  double wavelength, level;
};
constexpr Row kLimit[] = {{0.400, 17.1},  {0.315, 15.0}, {0.250, 13.0},  {0.200, 11.0},   {0.160, 9.0},  {0.125, 7.0},
                          {0.100, 4.9},   {0.080, 2.9},  {0.063, 0.9},   {0.050, -1.1},   {0.040, -3.2}, {0.0315, -5.0},
                          {0.025, -5.6},  {0.020, -6.2}, {0.016, -6.8},  {0.0125, -7.4},  {0.010, -8.0}, {0.008, -8.6},
                          {0.0063, -9.2}, {0.005, -9.8}, {0.004, -10.4}, {0.00315, -11.0}};
}  // namespace

std::vector<RoughnessBand> iso3095_rail_roughness_limit() {
  std::vector<RoughnessBand> out;
  for (const Row& r : kLimit) {
    RoughnessBand b{};
    b.wavelength_nominal = r.wavelength;
    b.level_db = r.level;
    const double x = std::round(10.0 * std::log10(1.0 / r.wavelength));  // base-ten band index of n = 1/lambda
    const double n_c = std::pow(10.0, x / 10.0);
    b.k_centre = 2.0 * M_PI * n_c;
    b.k_lower = b.k_centre * std::pow(10.0, -1.0 / 20.0);
    b.k_upper = b.k_centre * std::pow(10.0, 1.0 / 20.0);
    const double rms = 1e-6 * std::pow(10.0, r.level / 20.0);  // Eq. 10
    b.psd = rms * rms / (b.k_upper - b.k_lower);               // Eq. 11
    out.push_back(b);
  }
  return out;
}

TabulatedPsd iso3095_rail_psd(Extension extension) {
  const auto bands = iso3095_rail_roughness_limit();
  std::vector<double> k, g;
  // Listed from long to short wavelength, i.e. increasing k, as the table needs.
  for (const RoughnessBand& b : bands) {
    k.push_back(b.k_centre);
    g.push_back(b.psd);
  }
  return TabulatedPsd(std::move(k), std::move(g), extension);
}

}  // namespace rollspec::texture
