#include "kernels/texture/psd_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

BandAveragedPsd band_averaged_psd(const EstimatedPsd& e, const PsdBands& b) {
  if (b.bands_per_octave < 1 || b.min_bins < 1 || b.first_bin < 1)
    throw std::invalid_argument("PSD bands: bands_per_octave, min_bins and first_bin must be >= 1");
  if (e.psd.size() < 2) throw std::invalid_argument("PSD bands: the estimate has no bins");
  const std::size_t top = e.psd.size() - 1;  // the Nyquist bin N/2
  BandAveragedPsd out;
  // Octave [a, 2a) of bins (the last one ends at the Nyquist bin) in t geometric parts of at least
  // min_bins bins each (Eq. 33); an octave of fewer than min_bins bins (at the top, or below bin
  // min_bins) is widened to min_bins or joins the one below.
  for (std::size_t a = b.first_bin; a <= top;) {
    std::size_t end = std::min(std::max(2 * a, a + b.min_bins), top + 1);  // one past the octave's last bin
    if (top + 1 - end < b.min_bins) end = top + 1;
    const double ratio = static_cast<double>(end) / static_cast<double>(a);
    // Edge i of t parts: a ratio^{i/t}, rounded; t as large as bands_per_octave allows while the
    // first (smallest) part keeps min_bins.
    const auto edge = [&](std::size_t i, std::size_t t) {
      return i == t ? end
                    : static_cast<std::size_t>(std::lround(
                          static_cast<double>(a) * std::pow(ratio, static_cast<double>(i) / static_cast<double>(t))));
    };
    std::size_t t = std::min(b.bands_per_octave, (end - a) / b.min_bins);
    while (t > 1 && edge(1, t) < a + b.min_bins) --t;
    t = std::max<std::size_t>(t, 1);
    for (std::size_t i = 0; i < t; ++i) {
      const std::size_t j = edge(i, t), l = edge(i + 1, t) - 1;
      double sum = 0.0;
      for (std::size_t k = j; k <= l; ++k) sum += e.psd[k];
      out.first.push_back(j);
      out.last.push_back(l);
      out.psd.push_back(sum / static_cast<double>(l - j + 1));  // Eq. 33
      out.centre.push_back(e.dk *
                           std::sqrt((static_cast<double>(j) - 0.5) * (static_cast<double>(l) + 0.5)));  // Eq. 34
    }
    a = end;
  }
  if (out.psd.size() < 2)
    throw std::invalid_argument("PSD bands: " + std::to_string(top + 1 - b.first_bin) + " bins above bin " +
                                std::to_string(b.first_bin) + " make fewer than 2 bands of " +
                                std::to_string(b.min_bins) + " bins");
  return out;
}

TabulatedPsd smoothed_psd_table(const EstimatedPsd& e, Extension extension, const PsdBands& b) {
  const BandAveragedPsd a = band_averaged_psd(e, b);
  const std::size_t nb = a.psd.size();
  // Eq. 35: nodes at the band centres; the end nodes at the first band's lower edge (bin f_0
  // covers [(f_0 - 1/2) dk, (f_0 + 1/2) dk]) and at the Nyquist wavenumber, flat with their bands.
  std::vector<double> edge(nb + 1), power(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    edge[i] = e.dk * (static_cast<double>(a.first[i]) - 0.5);
    power[i] = a.psd[i] * static_cast<double>(a.last[i] - a.first[i] + 1) * e.dk;  // Eq. 33
  }
  edge[nb] = e.dk * static_cast<double>(e.psd.size() - 1);
  std::vector<double> k{edge.front()}, g{a.psd.front()};
  for (std::size_t i = 0; i < nb; ++i) {
    k.push_back(a.centre[i]);
    g.push_back(a.psd[i]);
  }
  k.push_back(edge.back());
  g.push_back(a.psd.back());
  // Eq. 41: the log-log interpolant between centres misplaces a band's power where the spectrum is
  // steep (a measured first band can hold half the variance in its lowest bin): scale each node
  // until the table's integral over every band is the band's power, so the table holds the
  // estimate's variance exactly. A multiplicative fixed point; 20-40 sweeps reach 1e-12.
  for (int sweep = 0; sweep < 500; ++sweep) {
    const TabulatedPsd t(k, g, Extension::zero);
    double worst = 0.0;
    std::vector<double> r(nb, 1.0);
    for (std::size_t i = 0; i < nb; ++i) {
      const double held = t.integral(edge[i], edge[i + 1]);
      if (held > 0.0 && power[i] > 0.0) r[i] = power[i] / held;
      worst = std::max(worst, std::abs(r[i] - 1.0));
    }
    if (worst < 1e-12) break;
    for (std::size_t i = 0; i < nb; ++i) g[i + 1] *= r[i];
    g.front() = g[1];
    g.back() = g[nb];
  }
  return TabulatedPsd(std::move(k), std::move(g), extension);
}

}  // namespace rollspec::texture
