#include "src/scenes/psd_rows.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

namespace rollspec::scenes {

PsdRows::PsdRows(std::vector<std::string> sensors, bool sensor_mean, std::vector<double> frequency, double band_min,
                 double band_max, std::size_t extras)
    : sensors_(sensors.size()),
      names_(std::move(sensors)),
      frequency_(std::move(frequency)),
      df_(frequency_.size() > 1 ? frequency_[1] - frequency_[0] : 1.0),
      band_min_(band_min),
      band_max_(band_max),
      bands_(io::result_bands(frequency_, band_min, band_max)),
      extras_(extras) {
  if (sensor_mean && sensors_ > 1) names_.emplace_back("sensor_mean");
}

void PsdRows::finish(double* values) const {
  const std::size_t nf = n_freq(), nb = bands_.size();
  if (rows() > sensors_)
    for (std::size_t k = 0; k < nf; ++k) {
      double m = 0.0;
      for (std::size_t s = 0; s < sensors_; ++s) m += values[s * nf + k];
      values[sensors_ * nf + k] = m / static_cast<double>(sensors_);
    }
  double* band = values + rows() * nf;
  for (std::size_t r = 0; r < rows(); ++r)
    for (std::size_t b = 0; b < nb; ++b)
      band[r * nb + b] = spectral::band_average(values + r * nf, nf, df_, bands_[b].lower, bands_[b].upper);
  // ln x for the lognormal law. A value without power (exactly 0, only for a signal without any)
  // takes ln DBL_MIN: finite, as the driver requires, and so far below the rest that the lognormal
  // law there widens the interval rather than pretend to fit.
  const std::size_t n = spectra();
  for (std::size_t i = 0; i < n; ++i) values[n + i] = std::log(std::max(values[i], DBL_MIN));
  double* product = values + 2 * n + extras_;
  for (std::size_t r = 0; r < rows(); ++r)
    for (std::size_t b = 0; b < nb; ++b)
      for (std::size_t c = b; c < nb; ++c) *product++ = values[band_log_index(r, b)] * values[band_log_index(r, c)];
  for (std::size_t r = 0; r < rows(); ++r)
    for (std::size_t b = 0; b < nb; ++b) {
      const double y = values[band_log_index(r, b)];
      *product++ = y * y * y;  // D-29: the skewness of the band logs
    }
}

ResultShape PsdRows::shape() const {
  ResultShape s{names_, frequency_, {}, {}};
  for (const auto& b : bands_) {
    s.band_lower.push_back(b.lower);
    s.band_upper.push_back(b.upper);
  }
  return s;
}

io::PsdEnsemble PsdRows::welch_ensemble(const ensemble::EnsembleSums& sums, const spectral::WelchPlan& welch,
                                        std::size_t record_samples, double confidence) const {
  io::PsdEnsemble e = ensemble(sums);
  e.welch_dof = static_cast<double>(sums.count) * welch.equivalent_dof(record_samples);
  e.window_enbw_bins = spectral::equivalent_noise_bandwidth_bins(welch.window());
  e.welch = welch.config();
  e.record_samples = record_samples;
  e.confidence = confidence;
  return e;
}

io::PsdEnsemble PsdRows::ensemble(const ensemble::EnsembleSums& sums) const {
  io::PsdEnsemble e;
  e.frequency = frequency_;
  e.sensors = names_;
  e.realisations = sums.count;
  e.band_min = band_min_;
  e.band_max = band_max_;
  const std::size_t n = rows() * n_freq(), nb = rows() * bands_.size(), logs = spectra();
  auto moments = [&](std::size_t i) {
    return spectral::Scatter{sums.mean(i), sums.std_dev(i), sums.mean(logs + i), sums.std_dev(logs + i)};
  };
  for (std::size_t i = 0; i < n; ++i) {
    e.mean.push_back(sums.mean(i));
    e.std_dev.push_back(sums.std_dev(i));
    e.scatter.push_back(moments(i));
  }
  for (std::size_t i = 0; i < nb; ++i) e.band_scatter.push_back(moments(n + i));
  // Between-band covariance of the band logs (K - 1), from the sums of their products (D-26).
  const std::size_t n_bands = bands_.size();
  const double K = static_cast<double>(sums.count);
  e.band_log_covariance.assign(rows() * n_bands * n_bands, sums.count > 1 ? 0.0 : NAN);
  std::size_t p = 2 * logs + extras_;
  for (std::size_t r = 0; r < rows(); ++r)
    for (std::size_t b = 0; b < n_bands; ++b)
      for (std::size_t c = b; c < n_bands; ++c, ++p) {
        if (sums.count < 2) continue;
        const double mb = sums.mean(band_log_index(r, b)), mc = sums.mean(band_log_index(r, c));
        const double v = (sums.sum[p] - K * mb * mc) / (K - 1.0);
        e.band_log_covariance[(r * n_bands + b) * n_bands + c] = v;
        e.band_log_covariance[(r * n_bands + c) * n_bands + b] = v;
      }
  for (std::size_t i = 0; i < nb; ++i, ++p) {  // D-29: from the sums of y, y^2 and y^3
    const std::size_t y = logs + n + i;
    e.band_tail.push_back(spectral::tail_check(sums.count, sums.sum[y], sums.sum_sq[y], sums.sum[p]));
  }
  return e;
}

}  // namespace rollspec::scenes
