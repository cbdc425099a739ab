#include "src/io/table_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernels/spectral/table_jackknife.hpp"
#include "src/io/psd_result.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::io {

std::vector<double> band_levels_db(const PsdEnsemble& e) {
  const std::size_t nf = e.frequency.size(), ns = e.sensors.size();
  const double df = nf > 1 ? e.frequency[1] - e.frequency[0] : 1.0;
  const auto bands = result_bands(e.frequency, e.band_min, e.band_max);
  std::vector<double> level(ns * bands.size());
  for (std::size_t b = 0; b < bands.size(); ++b)
    for (std::size_t s = 0; s < ns; ++s)
      level[s * bands.size() + b] =
          10.0 * std::log10(spectral::band_average(e.mean.data() + s * nf, nf, df, bands[b].lower, bands[b].upper));
  return level;
}

namespace {
// D-30c at value j of the paired sums: the runs' own noise in dB^2.
double paired_noise(const PairedSums& p, std::size_t j, std::vector<double>& m) {
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = p.means[i].at(j);
  return spectral::paired_noise_variance(p.q.at(j), m.data(), m.size(), p.realisations);
}

}  // namespace

TableError table_jackknife(const std::vector<PsdEnsemble>& sub_tables, const PairedSums& paired,
                           const std::string& table, const std::string& unit, double variance_factor, double dof) {
  TableError t;
  t.surfaces = sub_tables.size();
  t.dof = dof > 0.0 ? dof : static_cast<double>(t.surfaces) - 1.0;
  t.variance_factor = variance_factor;
  t.table = table;
  t.unit = unit;
  if (sub_tables.empty()) return t;
  const std::size_t n = sub_tables.size(), bins = sub_tables[0].mean.size();
  std::vector<std::vector<double>> bands;
  for (const auto& e : sub_tables) {
    if (e.mean.size() != bins) throw std::logic_error("table jackknife: sub-table spectra of different shapes");
    bands.push_back(band_levels_db(e));
  }
  const std::size_t nb = bands[0].size();
  for (const auto& b : bands) t.band_levels.insert(t.band_levels.end(), b.begin(), b.end());
  if (paired.means.size() != n || paired.q.size() != bins + nb)
    throw std::logic_error("table jackknife: paired sums of another shape than the spectra");
  std::vector<double> theta(n), m(n);
  t.bin_variance.resize(bins);
  t.bin_noise.resize(bins);
  for (std::size_t i = 0; i < bins; ++i) {
    for (std::size_t j = 0; j < n; ++j) theta[j] = 10.0 * std::log10(sub_tables[j].mean[i]);
    t.bin_variance[i] = variance_factor * spectral::jackknife_variance(theta.data(), n);
    t.bin_noise[i] = variance_factor * paired_noise(paired, i, m);
  }
  t.band_variance.resize(nb);
  t.band_noise.resize(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    for (std::size_t j = 0; j < n; ++j) theta[j] = bands[j].at(i);
    t.band_variance[i] = variance_factor * spectral::jackknife_variance(theta.data(), n);
    t.band_noise[i] = variance_factor * paired_noise(paired, bins + i, m);
  }
  return t;
}

double median_noise_ratio(const TableError& t) {
  std::vector<double> ratio;
  for (std::size_t i = 0; i < t.band_variance.size(); ++i) {
    const double j = t.band_variance[i], noise = std::min(t.band_noise[i], j), v = j - noise;
    if (!(j > 0.0) || !std::isfinite(j) || !std::isfinite(noise)) continue;
    ratio.push_back(v > 0.0 ? noise / v : HUGE_VAL);
  }
  if (ratio.empty()) return 0.0;
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2), ratio.end());
  return ratio[ratio.size() / 2];
}

std::string table_noise_warning(const TableError& t, std::uint64_t K) {
  std::vector<double> share, ratio;  // noise / jackknife, and noise / table term, per band
  for (std::size_t i = 0; i < t.band_variance.size(); ++i) {
    const double j = t.band_variance[i], noise = std::min(t.band_noise[i], j), v = j - noise;
    if (!(j > 0.0) || !std::isfinite(j) || !std::isfinite(noise)) continue;
    share.push_back(noise / j);
    ratio.push_back(v > 0.0 ? noise / v : HUGE_VAL);
  }
  if (share.empty()) return "";
  const auto median = [](std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2), x.end());
    return x[x.size() / 2];
  };
  const double noise = median(share), r = median(ratio);
  if (noise <= 0.5) return "";
  std::string text;
  const std::string k_needed =
      std::isfinite(r) ? "about " + std::to_string(static_cast<long long>(std::ceil(4.0 * r * static_cast<double>(K))))
                       : "enough realisations that the table's term shows above it";
  text = io::formatted(
      "table jackknife: %.0f %% of the jackknife variance (median over the bands) is the sub-table runs' own "
      "noise, not the table's (the realisations are chaotic in the table), so with %llu realisations per "
      "sub-table the intervals are wider than the table's error alone needs (kernels/spectral D-30c, D-30f); ",
      100.0 * noise, static_cast<unsigned long long>(K));
  return text + k_needed + " would bring the noise to a quarter of the table's term";
}

std::string interval_includes(const TableError& t) {
  if (t.surfaces > 0)
    return "realisations, " + t.table + " (jackknife over " + std::to_string(t.surfaces) + " " + t.unit + ")";
  if (!t.table.empty()) return "realisations only (conditional on the " + t.table + ")";
  return "realisations";
}

void widen_band_interval(double level, double& lo, double& hi, double v, double table_dof, std::uint64_t K,
                         double level_p) {
  if (!std::isfinite(level)) return;
  lo = level - spectral::widen_half_width(level - lo, K, v, table_dof, level_p).half_width;
  hi = level + spectral::widen_half_width(hi - level, K, v, table_dof, level_p).half_width;
}

void widen_bin_interval(double mean, double& lo, double& hi, double v, double table_dof, std::uint64_t K,
                        double level_p) {
  if (!(mean > 0.0) || !(lo > 0.0) || !std::isfinite(hi)) return;
  const double db = 10.0 * std::log10(mean);
  double lo_db = 10.0 * std::log10(lo), hi_db = 10.0 * std::log10(hi);
  widen_band_interval(db, lo_db, hi_db, v, table_dof, K, level_p);
  lo = std::pow(10.0, lo_db / 10.0);
  hi = std::pow(10.0, hi_db / 10.0);
}

}  // namespace rollspec::io
