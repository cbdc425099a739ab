// rollspec fit's search as an engine function (src/fit/fit_search.hpp), without the command: a known
// force level of the random oscillator recovered inside its interval from a synthetic measurement made
// by the engine's own run (run::run_request), as tests/cli/test_fit.py checks it through the command.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/compare/measured_psd.hpp"
#include "src/fit/fit_model.hpp"
#include "src/fit/fit_search.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/run/run_phases.hpp"

using namespace rollspec;
namespace fs = std::filesystem;

namespace {
// The fast oscillator of tests/cli/fit_experiment.py: 4 s records at 1024 Hz, nine bands around 50 Hz.
const std::vector<std::string> kFast = {"signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048",
                                        "spectrum.band_min=20", "spectrum.band_max=200"};
constexpr double kTruth = 2.0;  // force.level, N^2/Hz
constexpr double kRecords = 16.0;

// M records of the study at the truth and another seed, their sensor-mean PSD as a measured CSV.
std::string measurement(const fs::path& dir, const std::string& study) {
  run::RunRequest q;
  q.study.file = study;
  q.study.sets = kFast;
  for (const char* s : {"force.level=2", "study.realisations=16", "study.seed=4242"}) q.study.sets.push_back(s);
  q.out = (dir / "m.h5").string();
  q.quiet = true;
  REQUIRE(run::run_request(q) == 0);
  const io::Hdf5Reader r(q.out);
  std::vector<std::size_t> dims;
  const std::vector<double> f = r.read("/psd/frequency"), psd = r.read("/psd/mean", &dims);
  REQUIRE(dims.size() == 2);
  const std::size_t last = (dims[0] - 1) * dims[1];  // the sensor mean's row
  const std::string csv = (dir / "m.csv").string();
  std::ofstream out(csv);
  out << "frequency_hz,psd\n";
  char line[80];
  for (std::size_t i = 1; i < f.size(); ++i) {  // bin 0 left out, as a measured PSD has no mean
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", f[i], psd[last + i]);
    out << line;
  }
  return csv;
}
}  // namespace

TEST_CASE("fit_search recovers a known force level inside its interval, in-process") {
  const fs::path dir = fs::temp_directory_path() / "rollspec_test_fit_search";
  fs::remove_all(dir);
  fs::create_directories(dir / "runs");
  const std::string study = (fs::path(ROLLSPEC_SOURCE_DIR) / "studies" / "random-oscillator.ini").string();
  fit::FitInputs in;
  in.study = study;
  in.sets = kFast;
  in.sets.push_back("study.realisations=40");
  in.vary.push_back(fit::parse_vary("force.level=0.1:10:log"));
  fit::FitPoint p;
  p.path = measurement(dir, study);
  p.records = kRecords;
  std::string column;
  p.measurement = compare::read_measurement(p.path, column, -1, "fit");
  in.points.push_back(std::move(p));
  fit::check_fit_keys(in);
  fit::FitModel model(in, (dir / "runs").string());
  const fit::FitReport r = fit::fit_search(model, in);

  REQUIRE(r.parameters.size() == 1);
  const fit::FitParameter& k = r.parameters[0];
  CHECK(k.key == "force.level");
  CHECK(k.lower < k.estimate);
  CHECK(k.estimate < k.upper);
  // 16 records of nine bands pin the level to a few per cent; the truth within twice the half-width
  // (about 3.9 sigma) fails once in 10^4 experiments.
  CHECK(std::abs(k.estimate / kTruth - 1.0) < 0.05);
  CHECK(std::abs(k.estimate - kTruth) < (k.upper - k.lower));
  CHECK(k.upper / k.lower < 1.15);
  // A linear scene: common random numbers hold, so ln L is the study seed's and the interval is a profile.
  CHECK(r.objective.common_random_numbers);
  CHECK(r.no_interval.empty());
  CHECK(r.bands == 9);
  CHECK(r.evaluations > 10);
  CHECK(r.evaluations < 100);
  CHECK(r.points.size() == 1);
  CHECK(r.test_defined);
  CHECK(r.p_value > 0.0);
  CHECK(r.p_value <= 1.0);
  fs::remove_all(dir);
}
