#include "src/compare/combined_test.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernels/spectral/band_law.hpp"
#include "kernels/spectral/band_test_table.hpp"
#include "kernels/spectral/ensemble_interval.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::compare {

ChosenBands chosen_bands(const io::BandLevels& b, const std::vector<std::size_t>& band,
                         const std::vector<double>& measured_db) {
  const std::size_t p = band.size(), nb = b.level_db.size();
  const bool skewness = b.log_skewness.size() == nb;
  ChosenBands c{std::vector<double>(p), std::vector<double>(p), std::vector<double>(p * p),
                std::vector<double>(skewness ? p : 0)};
  for (std::size_t i = 0; i < p; ++i) {
    c.y[i] = measured_db[i] * std::log(10.0) / 10.0;
    c.mean[i] = std::pow(10.0, b.level_db[band[i]] / 10.0);
    for (std::size_t j = 0; j < p; ++j) c.cov[i * p + j] = b.log_covariance[band[i] * nb + band[j]];
    if (!skewness) continue;
    const double s = c.cov[i * p + i];  // D-26d; a damaged variance gives NaN, which the test refuses in one line
    c.cv2[i] = s >= 0.0 && std::isfinite(s) ? spectral::band_cv2(s, b.log_skewness[band[i]]) : NAN;
  }
  return c;
}

double table_band_variance_db(const io::BandLevels& b, std::size_t k) {
  const auto c = io::table_log_covariance(b, {k});
  const double to_db = 10.0 / std::log(10.0);
  return c.empty() ? 0.0 : c[0] * to_db * to_db;
}

CombinedTest combined_test(const io::BandLevels& b, const std::vector<std::size_t>& band,
                           const std::vector<double>& measured_db, double records, double level, double table_factor,
                           const spectral::BandNoise* noise) {
  CombinedTest t;
  t.bands = band.size();
  t.level = level;
  if (!(records > 0.0)) {
    t.verdict = "none (give --measured-averages M: the test asks whether the measurement is a mean of M records)";
    return t;
  }
  if (b.log_covariance.empty()) {
    t.verdict = "none (the result has no /bands/log_level_covariance: re-run it with this rollspec)";
    return t;
  }
  const std::size_t p = band.size();
  const ChosenBands c = chosen_bands(b, band, measured_db);
  const std::vector<double> table = table_factor > 0.0 ? io::table_log_covariance(b, band) : std::vector<double>{};
  const spectral::DrawUniforms uniform = [](std::uint64_t draw, double* u, std::size_t n) {
    rng::PhiloxStream(rng::kVerdictSeed, draw, rng::Stream::verdict_bootstrap).uniform_open(u, n);
  };
  try {
    t.result = spectral::band_test_with_table(
        c.y.data(), c.mean.data(), c.cov.data(), p, b.realisations, records,
        {table.empty() ? nullptr : table.data(), b.table_dof, table_factor, b.table_independent_bands,
         b.table_independent_bands ? kSpectralTableSmoothing : 0, io::table_shrinkage(b, band)},
        uniform, kBootstrapDraws, noise, c.cv2_or_null());
  } catch (const std::invalid_argument& e) {
    t.verdict = std::string("none (") + e.what() + ")";
    return t;
  }
  if (!t.result.defined) {
    t.verdict = "none (" + std::to_string(p) + " bands need K >= " + std::to_string(t.result.needed) +
                " realisations, the result has " + std::to_string(b.realisations) +
                "; run more or choose fewer bands with --fmin/--fmax)";
    return t;
  }
  t.rejected = t.result.p_value < level;
  std::string buf;
  if (t.result.draws > 0 && !(table_factor > 0.0))
    buf = io::formatted(
        "%s at level %g: p = %.3g (T2 = %.4g, %zu bands; law of T2 with the logger noise's terms by a "
        "parametric bootstrap of %zu draws, kernels/spectral D-31b, D-33f)",
        t.rejected ? "REJECTED" : "not rejected", level, t.result.p_value, t.result.t2, p, t.result.draws);
  else if (t.result.draws > 0)
    buf = io::formatted(
        "%s at level %g: p = %.3g (T2 = %.4g, %zu bands; law of T2 with the %s's error by a parametric "
        "bootstrap of %zu draws, kernels/spectral D-31b)",
        t.rejected ? "REJECTED" : "not rejected", level, t.result.p_value, t.result.t2, p, b.table.c_str(),
        t.result.draws);
  else
    buf = io::formatted("%s at level %g: p = %.3g (T2 = %.4g, F = %.4g on %g, %g dof, %zu bands)",
                        t.rejected ? "REJECTED" : "not rejected", level, t.result.p_value, t.result.t2, t.result.f,
                        t.result.dof1, t.result.dof2, p);
  t.verdict = buf;
  return t;
}

}  // namespace rollspec::compare
