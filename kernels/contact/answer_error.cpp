#include "kernels/contact/answer_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/third_octave_bands.hpp"

namespace rollspec::contact {

double white_error_band_db(const spectral::WelchConfig& config, std::size_t samples, const std::vector<double>& psd,
                           std::size_t first_bin, double error_psd, double lower, double upper) {
  const std::size_t bins = config.segment / 2 + 1;
  if (psd.size() != bins || first_bin >= bins || samples < config.segment)
    throw std::invalid_argument("white_error_band_db: the PSD's bins, first_bin and samples do not fit the Welch plan");
  if (!(error_psd >= 0.0) || !(upper >= lower))
    throw std::invalid_argument("white_error_band_db: needs error_psd >= 0 and upper >= lower");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double df = config.sample_rate / static_cast<double>(config.segment);
  const double first = (static_cast<double>(first_bin) - 0.5) * df, last = (static_cast<double>(bins) - 0.5) * df;
  if (lower >= last) return nan;
  if (upper <= first) {  // below the first bin: that bin's error (BF-9c)
    lower = first;
    upper = first + df;
  }
  lower = std::max(lower, first);
  upper = std::min(upper, last);
  const double level = spectral::band_average(psd.data(), bins, df, lower, upper);
  const double nu = spectral::BandDof(config)(samples, lower, upper);
  if (!(level > 0.0) || !(nu > 0.0)) return nan;
  const double r = error_psd / level;
  return 10.0 / std::log(10.0) * std::sqrt(r * r + 4.0 * r / nu);
}

}  // namespace rollspec::contact
