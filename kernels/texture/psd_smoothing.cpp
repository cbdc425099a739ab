#include "kernels/texture/psd_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

BandAveragedPsd band_averaged_psd(const EstimatedPsd& e, const PsdBands& b) {
  if (b.bands_per_decade < 1 || b.min_bins < 1 || b.first_bin < 1)
    throw std::invalid_argument("PSD bands: bands_per_decade, min_bins and first_bin must be >= 1");
  if (e.psd.size() < 2) throw std::invalid_argument("PSD bands: the estimate has no bins");
  const std::size_t top = e.psd.size() - 1;  // the Nyquist bin N/2
  const double ratio = std::pow(10.0, 1.0 / static_cast<double>(b.bands_per_decade));
  BandAveragedPsd out;
  for (std::size_t j = b.first_bin; j <= top;) {
    // Bin i covers [i - 1/2, i + 1/2] dk: the band ends at the last bin inside (j - 1/2) ratio.
    const double edge = (static_cast<double>(j) - 0.5) * ratio;
    std::size_t l = edge > 0.5 ? static_cast<std::size_t>(std::floor(edge - 0.5)) : j;
    l = std::max(l, j + b.min_bins - 1);
    if (l + b.min_bins > top) l = top;  // too few bins left for a band of their own: merge them
    double sum = 0.0;
    for (std::size_t i = j; i <= l; ++i) sum += e.psd[i];
    out.first.push_back(j);
    out.last.push_back(l);
    out.psd.push_back(sum / static_cast<double>(l - j + 1));  // Eq. 33
    out.centre.push_back(e.dk * std::sqrt((static_cast<double>(j) - 0.5) * (static_cast<double>(l) + 0.5)));  // Eq. 34
    j = l + 1;
  }
  if (out.psd.size() < 2)
    throw std::invalid_argument("PSD bands: " + std::to_string(top + 1 - b.first_bin) + " bins above bin " +
                                std::to_string(b.first_bin) + " make fewer than 2 bands of " + std::to_string(b.min_bins) +
                                " bins");
  return out;
}

TabulatedPsd smoothed_psd_table(const EstimatedPsd& e, Extension extension, const PsdBands& b) {
  const BandAveragedPsd a = band_averaged_psd(e, b);
  // Eq. 35: the end nodes repeat the end bands' values (flat over half a band), so the table covers
  // [first bin, Nyquist] like the raw one and the generators' sampling checks see the same k_max.
  std::vector<double> k{e.dk * static_cast<double>(b.first_bin)}, g{a.psd.front()};
  for (std::size_t i = 0; i < a.psd.size(); ++i) {
    k.push_back(a.centre[i]);
    g.push_back(a.psd[i]);
  }
  k.push_back(e.dk * static_cast<double>(e.psd.size() - 1));
  g.push_back(a.psd.back());
  return TabulatedPsd(std::move(k), std::move(g), extension);
}

}  // namespace rollspec::texture
