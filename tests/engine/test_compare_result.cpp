// rollspec compare's engine function (src/compare/comparison.hpp), without the command: a result compared
// with a PSD table of its own mean lies inside every band's prediction interval with a combined test far
// from rejection, and the same table in g read as m/s^2 is named as a unit slip, rejected, and offset by
// 20 log10 9.80665 dB; a bad option is refused before any file is read.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/compare/comparison.hpp"
#include "src/compare/comparison_json.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/run/run_phases.hpp"
#include "tests/engine/scratch_directory.hpp"

using namespace rollspec;
namespace fs = std::filesystem;

namespace {
constexpr double kG = 9.80665;  // m/s^2 per g

// The random oscillator's fast study of test_fit_search: 4 s records at 1024 Hz, nine bands around 50 Hz.
std::string model_run(const fs::path& dir) {
  run::RunRequest q;
  q.study.file = (fs::path(ROLLSPEC_SOURCE_DIR) / "studies" / "random-oscillator.ini").string();
  q.study.sets = {"signal.duration=4",    "signal.sample_rate=1024", "spectrum.segment=2048",
                  "spectrum.band_min=20", "spectrum.band_max=200",   "study.realisations=16"};
  q.out = (dir / "model.h5").string();
  q.quiet = true;
  REQUIRE(run::run_request(q) == 0);
  return q.out;
}

// The result's last PSD row (the oscillator's one sensor) times `factor`, as a measured PSD table on the model's own
// bins (bin 0 included), so its bands average what the model's do.
std::string own_mean_table(const std::string& result, const fs::path& path, double factor) {
  const io::Hdf5Reader r(result);
  std::vector<std::size_t> dims;
  const std::vector<double> f = r.read("/psd/frequency"), psd = r.read("/psd/mean", &dims);
  REQUIRE(dims.size() == 2);
  const std::size_t last = (dims[0] - 1) * dims[1];
  std::ofstream out(path);
  out << "frequency_hz,psd\n";
  char line[80];
  for (std::size_t i = 0; i < f.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", f[i], psd[last + i] * factor);
    out << line;
  }
  return path.string();
}
}  // namespace

TEST_CASE("compare_result: a result against its own mean, and the same in g read as m/s^2") {
  const fs::path dir = test::fresh_directory("rollspec_test_compare_result");
  compare::CompareRequest q;
  q.result = model_run(dir);
  q.measured_averages = 16.0;

  q.measurements = {own_mean_table(q.result, dir / "own.csv", 1.0)};
  const compare::Comparison own = compare::compare_result(q);
  CHECK(own.psd_table);
  CHECK(own.measurement.model_grid);
  CHECK(own.predict);
  CHECK(own.bands.sensor == "mass");  // the oscillator's one row
  REQUIRE(own.verdict.rows.size() == 9);
  for (const auto& row : own.verdict.rows) {
    CHECK(row.use == compare::BandUse::test);
    CHECK(row.inside_prediction);
    CHECK(std::abs(row.delta) < 1e-9);  // the model's own bins, every digit
  }
  CHECK(own.verdict.tested == 9);
  CHECK(own.verdict.inside == 9);
  REQUIRE(own.verdict.test.result.defined);
  CHECK(!own.verdict.test.rejected);
  CHECK(own.verdict.test.result.p_value > 0.5);
  CHECK(own.verdict.warnings.empty());
  REQUIRE(own.verdict.offset);
  CHECK(own.verdict.offset->lower < 0.0);
  CHECK(own.verdict.offset->upper > 0.0);

  // A measurement in g read as m/s^2: every band 19.83 dB under the model.
  q.measurements = {own_mean_table(q.result, dir / "in_g.csv", 1.0 / (kG * kG))};
  const compare::Comparison slip = compare::compare_result(q);
  REQUIRE(slip.verdict.rows.size() == 9);
  for (std::size_t k = 0; k < 9; ++k) {
    CHECK(!slip.verdict.rows[k].inside_prediction);
    CHECK(slip.verdict.rows[k].delta - own.verdict.rows[k].delta ==
          doctest::Approx(20.0 * std::log10(kG)).epsilon(1e-9));
  }
  bool named = false;
  for (const auto& w : slip.verdict.warnings)
    named |= w.find("a recording in g read as m/s^2 (--unit g)") != std::string::npos;
  CHECK(named);
  bool said = false;  // and among the lines the command prints on stderr
  for (const auto& line : slip.messages)
    said |= line.rfind("WARNING: ", 0) == 0 && line.find("--unit g") != std::string::npos;
  CHECK(said);
  REQUIRE(slip.verdict.test.result.defined);
  CHECK(slip.verdict.test.rejected);
  CHECK(slip.verdict.test.result.p_value < 1e-6);
  REQUIRE(slip.verdict.offset);
  CHECK(slip.verdict.offset->estimate - own.verdict.offset->estimate ==
        doctest::Approx(20.0 * std::log10(kG)).epsilon(1e-9));

  // The JSON the command prints and the module returns: the same numbers.
  const auto j = compare::comparison_json(slip);
  CHECK(j["bands"].size() == 9);
  CHECK(j["p_value"].get<double>() == slip.verdict.test.result.p_value);
  CHECK(j["measured_averages"].get<double>() == 16.0);
  CHECK(j["bands"][0]["inside"].get<bool>() == false);
  fs::remove_all(dir);
}

TEST_CASE("compare_result refuses a bad option before reading any file") {
  compare::CompareRequest q;
  q.result = "no such result.h5";
  q.measurements = {"no such measurement.csv"};
  q.fmin = 100.0;
  q.fmax = 50.0;
  try {
    compare::compare_result(q);
    FAIL("no refusal");
  } catch (const UserError& e) {
    CHECK(e.exit_code() == EX_USAGE);
    CHECK(std::string(e.what()) == "--fmax 50: allowed: a frequency above --fmin (100 Hz)");
  }
  q.fmax = INFINITY;
  q.measured_averages = 0.5;
  CHECK_THROWS_WITH_AS(compare::compare_result(q),
                       "--measured-averages 0.5: allowed: a finite count >= 1 of independent rolls", UserError);
  q.measured_averages.reset();
  try {  // every option good: the missing measurement is what is refused
    compare::compare_result(q);
    FAIL("no refusal");
  } catch (const UserError& e) {
    CHECK(e.exit_code() == EX_NOINPUT);
  }
}
