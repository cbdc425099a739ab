// BF-9c (answer_error.hpp): the band-level error a white error in a sequence gives its Welch PSD, against
// Monte Carlo: a smooth random sequence plus Philox white noise of known variance, put through the same
// Welch plan, many draws; the formula's rms error within 20 % of the draws' in every band.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "../spectral/philox_draws.hpp"
#include "kernels/contact/answer_error.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"

using rollspec::contact::white_error_band_db;
using rollspec::spectral::WelchConfig;
using rollspec::spectral::WelchPlan;
using rollspec::spectral::WelchWorkspace;
using Normals = rollspec::spectral::testing::PhiloxNormals;

TEST_CASE("a white error's band-level error (BF-9c) is what Monte Carlo gives") {
  const std::size_t n = 1024, segment = 256;
  const double step = 20e-6;  // m
  WelchConfig wc;
  wc.sample_rate = 1.0 / step;
  wc.segment = segment;
  wc.overlap = segment / 2;
  const WelchPlan plan(wc);
  WelchWorkspace ws(segment);
  const std::size_t bins = plan.n_freq();
  std::vector<double> k(bins);
  for (std::size_t j = 0; j < bins; ++j) k[j] = plan.frequency_step() * static_cast<double>(j);  // cycles/m
  // Bands of a third octave from bin 3 up (the levels the F0 table's callers read).
  std::vector<std::pair<double, double>> bands;
  for (double c = 4.0 * k[1]; c * std::pow(2.0, 1.0 / 6.0) < k.back(); c *= std::pow(2.0, 1.0 / 3.0))
    bands.emplace_back(c * std::pow(2.0, -1.0 / 6.0), c * std::pow(2.0, 1.0 / 6.0));
  REQUIRE(bands.size() >= 6);
  const auto band_level = [&](const std::vector<double>& psd, double lo, double hi) {
    return 10.0 * std::log10(rollspec::spectral::band_average(psd.data(), bins, k[1], lo, hi));
  };
  for (const double sigma : {0.003, 0.03}) {  // the error's rms against a signal of rms ~1
    Normals g(11);
    std::vector<double> f(n), fe(n), p(bins), pe(bins), mean_psd(bins, 0.0);
    std::vector<double> sq(bands.size(), 0.0);
    const int draws = 300;
    for (int d = 0; d < draws; ++d) {
      // A red signal (AR(1), coefficient 0.9): its PSD falls over the bands, as F0's does.
      double prev = 0.0;
      for (std::size_t i = 0; i < n; ++i) f[i] = prev = 0.9 * prev + std::sqrt(1 - 0.81) * g.next();
      for (std::size_t i = 0; i < n; ++i) fe[i] = f[i] + sigma * g.next();
      plan.psd(f.data(), n, p.data(), ws);
      plan.psd(fe.data(), n, pe.data(), ws);
      for (std::size_t j = 0; j < bins; ++j) mean_psd[j] += p[j] / draws;
      for (std::size_t b = 0; b < bands.size(); ++b) {
        const double e =
            band_level(pe, bands[b].first, bands[b].second) - band_level(p, bands[b].first, bands[b].second);
        sq[b] += e * e / draws;
      }
    }
    // The formula with the signal's mean PSD (one draw's is what the engine has; the mean isolates the formula).
    const double error_psd = 2.0 * sigma * sigma * step;
    for (std::size_t b = 0; b < bands.size(); ++b) {
      const double est = white_error_band_db(wc, n, mean_psd, 3, error_psd, bands[b].first, bands[b].second);
      const double mc = std::sqrt(sq[b]);
      CHECK(est / mc > 0.8);
      CHECK(est / mc < 1.2);
      MESSAGE("sigma " << sigma << ", band " << bands[b].first << ".." << bands[b].second << " /m: formula " << est
                       << " dB, Monte Carlo " << mc << " dB");
    }
  }
  CHECK_THROWS_AS(white_error_band_db(wc, n, std::vector<double>(3), 3, 1.0, 0.0, 1.0), std::invalid_argument);
  CHECK(std::isnan(white_error_band_db(wc, n, std::vector<double>(bins, 1.0), 3, 1.0, 2 * k.back(), 3 * k.back())));
  // Below the first bin: that bin's error.
  const std::vector<double> flat(bins, 1.0);
  CHECK(white_error_band_db(wc, n, flat, 3, 0.01, 0.2 * k[1], 0.5 * k[1]) ==
        doctest::Approx(white_error_band_db(wc, n, flat, 3, 0.01, 2.5 * k[1], 3.5 * k[1])).epsilon(1e-12));
}
