// run's check that K realisations suffice for the band intervals (kernels/spectral D-29).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "kernels/spectral/tail_check.hpp"
#include "src/io/band_tail_check.hpp"

using namespace rollspec;

namespace {

// Two rows x three bands; band b of row r from the logs y (K values each).
io::PsdEnsemble ensemble_of(const std::vector<std::vector<double>>& logs, std::uint64_t K) {
  io::PsdEnsemble e;
  e.sensors = {"sensor_1", "sensor_2"};
  e.realisations = K;
  for (const auto& y : logs) e.band_tail.push_back(spectral::tail_check_reference(y.data(), K));
  return e;
}

std::vector<spectral::Band> three_bands() { return spectral::third_octave_bands(350.0, 720.0); }

}  // namespace

TEST_CASE("a band whose logs carry one outlier among 25 is named, with the K it needs") {
  const auto bands = three_bands();
  REQUIRE(bands.size() == 3);
  std::vector<double> plain(25), outlier(25, -9.0);
  for (int k = 0; k < 25; ++k) plain[static_cast<std::size_t>(k)] = -9.0 + 0.1 * std::sin(1.7 * k);
  outlier[12] = -9.0 + std::log(30.0);
  const io::BandTailVerdict v =
      io::band_tail_verdict(ensemble_of({plain, plain, plain, plain, outlier, plain}, 25), bands);
  CHECK(v.short_of);
  const spectral::TailCheck t = spectral::tail_check_reference(outlier.data(), 25);
  CHECK(v.needed == t.needed);
  CHECK(v.needed > 25);
  CHECK(v.text.find("too few for the 500 Hz band of sensor_2") != std::string::npos);
  CHECK(v.text.find("asks for K >= " + std::to_string(t.needed)) != std::string::npos);
}

TEST_CASE("nearly symmetric logs pass; fewer than 5 realisations are not checked") {
  const auto bands = three_bands();
  std::vector<double> plain(25);
  for (int k = 0; k < 25; ++k) plain[static_cast<std::size_t>(k)] = -9.0 + 0.1 * std::sin(1.7 * k);
  const io::BandTailVerdict v =
      io::band_tail_verdict(ensemble_of(std::vector<std::vector<double>>(6, plain), 25), bands);
  CHECK_FALSE(v.short_of);
  CHECK(v.needed <= 25);
  CHECK(v.text.find("25 realisations enough in every band") != std::string::npos);
  const io::BandTailVerdict few =
      io::band_tail_verdict(ensemble_of(std::vector<std::vector<double>>(6, plain), 4), bands);
  CHECK_FALSE(few.short_of);
  CHECK(few.text == "not checked: no band intervals");
}
