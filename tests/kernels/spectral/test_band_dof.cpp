// D-33c a: the equivalent degrees of freedom of a band average of a Welch estimate of white noise. The fast
// form (FFT of the window products) against the direct sums, its one-bin case against D-16, and the moments of
// Philox white noise put through WelchPlan and band_average.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "kernels/spectral/band_dof.hpp"
#include "philox_draws.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"

using namespace rollspec::spectral;

namespace {

using Normals = testing::PhiloxNormals;

WelchConfig config(std::size_t segment, std::size_t overlap, Window w, Detrend d) {
  WelchConfig c;
  c.sample_rate = 1000.0;
  c.segment = segment;
  c.overlap = overlap;
  c.window = w;
  c.detrend = d;
  return c;
}

}  // namespace

TEST_CASE("band weights are band_average's rule") {
  const std::size_t n = 65;
  const double df = 7.8125;
  std::vector<double> psd(n);
  for (std::size_t k = 0; k < n; ++k)
    psd[k] = 1.0 + std::sin(0.37 * static_cast<double>(k)) + 0.01 * static_cast<double>(k * k);
  for (const auto& [lo, hi] : {std::pair{0.0, 3.0}, {11.2, 14.1}, {100.0, 180.0}, {300.0, 500.0}, {489.0, 500.0}}) {
    const BandWeights b = band_weights(n, df, lo, hi);
    double sum = 0.0;
    for (std::size_t i = 0; i < b.weight.size(); ++i) sum += b.weight[i] * psd[b.first + i];
    CHECK(sum == doctest::Approx(band_average(psd.data(), n, df, lo, hi)).epsilon(1e-14).scale(0.0));
  }
}

TEST_CASE("a band inside one bin has D-16's degrees of freedom") {
  for (const auto& c :
       {config(256, 128, Window::hann, Detrend::constant), config(256, 0, Window::rectangular, Detrend::none),
        config(256, 192, Window::hann, Detrend::none)}) {
    const WelchPlan plan(c);
    const BandDof dof(c);
    const double df = plan.frequency_step(), f = 40.0 * df;  // bin 40: its mean and its mirror play no part
    for (const std::size_t n : {256u, 700u, 3000u})
      CHECK(dof(n, f - 0.2 * df, f + 0.3 * df) == doctest::Approx(plan.equivalent_dof(n)).epsilon(1e-10).scale(0.0));
  }
}

TEST_CASE("the FFT form equals the direct sums, near DC (the mean's removal), mid-band and at Nyquist") {
  for (const auto& c :
       {config(64, 32, Window::hann, Detrend::constant), config(64, 32, Window::hann, Detrend::none),
        config(64, 48, Window::hann, Detrend::constant), config(63, 20, Window::hann, Detrend::constant),
        config(64, 0, Window::rectangular, Detrend::constant), config(64, 16, Window::rectangular, Detrend::none)}) {
    const BandDof dof(c);
    const double df = c.sample_rate / static_cast<double>(c.segment), nyquist = c.sample_rate / 2.0;
    for (const auto& band : {std::pair{0.0, 2.4 * df},
                             {0.6 * df, 1.4 * df},
                             {1.1 * df, 4.7 * df},
                             {7.3 * df, 19.9 * df},
                             {nyquist - 3.2 * df, nyquist},
                             {3.0 * df, nyquist}})
      for (const std::size_t n : {64u, 200u, 641u}) {
        // named copies, not structured bindings: Clang 14 cannot capture those in INFO's lambda (C++17)
        const double lo = band.first, hi = band.second;
        const double fast = dof(n, lo, hi), direct = band_dof_reference(c, n, lo, hi);
        INFO("segment " << c.segment << " overlap " << c.overlap << " band " << lo << " .. " << hi << " n " << n);
        CHECK(direct > 0.0);
        CHECK(fast == doctest::Approx(direct).epsilon(1e-10).scale(0.0));
      }
    CHECK(dof(c.segment - 1, 0.0, 10.0 * df) == 0.0);  // shorter than a segment
  }
}

TEST_CASE("Monte-Carlo: white noise's band averages have 2 E^2 / var = nu_b") {
  // 20 000 records of Philox white noise through WelchPlan and band_average. The sample variance of a scaled
  // chi^2(nu) has a relative standard error sqrt((2 + 12 / nu) / R), below 1.2 % here; the tolerance is 5 %. The
  // bins of a band are not independent: the widest band's 14.5 bins times D-16's 20.9 per bin would be 303.
  const WelchConfig c = config(128, 64, Window::hann, Detrend::constant);
  const WelchPlan plan(c);
  WelchWorkspace ws(c.segment);
  const BandDof dof(c);
  const std::size_t n = 128 * 6, records = 20000;
  const double df = plan.frequency_step();
  const std::vector<std::pair<double, double>> bands = {{0.0, 2.6 * df}, {3.5 * df, 4.5 * df}, {9.7 * df, 24.2 * df}};
  std::vector<double> sum(bands.size()), sq(bands.size()), x(n), p(plan.n_freq());
  Normals normal(33);
  for (std::size_t r = 0; r < records; ++r) {
    for (double& v : x) v = normal.next();
    plan.psd(x.data(), n, p.data(), ws);
    for (std::size_t b = 0; b < bands.size(); ++b) {
      const double avg = band_average(p.data(), p.size(), df, bands[b].first, bands[b].second);
      sum[b] += avg;
      sq[b] += avg * avg;
    }
  }
  for (std::size_t b = 0; b < bands.size(); ++b) {
    const double mean = sum[b] / records, var = (sq[b] - records * mean * mean) / (records - 1.0);
    const double nu = dof(n, bands[b].first, bands[b].second);
    INFO("band " << bands[b].first << " .. " << bands[b].second << " Hz: nu_b " << nu);
    CHECK(2.0 * mean * mean / var == doctest::Approx(nu).epsilon(0.05).scale(0.0));
  }
}
