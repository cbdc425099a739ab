// One point of a sweep result read by number or by its swept values (src/io/sweep_point.hpp), and
// read_band_levels at that point: the stacked band datasets of a crossed 2 x 3 sweep, each point's
// levels distinct, so a wrong offset reads another point's numbers.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "src/error.hpp"
#include "src/io/band_levels.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/hdf5_stack.hpp"
#include "src/io/sweep_point.hpp"
#include "tests/engine/scratch_directory.hpp"

namespace fs = std::filesystem;
using namespace rollspec;

namespace {

// A result with two sensors and two bands whose levels are 100 * point + 10 * sensor + band.
void write_point(const std::string& path, int point) {
  io::Hdf5Writer w(path);
  w.attribute("/", "filetype", std::string("rollspec-result"));
  std::vector<double> level, zero(4, 0.0), one(4, 1.0);
  for (int s = 0; s < 2; ++s)
    for (int b = 0; b < 2; ++b) level.push_back(100.0 * point + 10.0 * s + b);
  std::vector<double> lower = {90.0, 110.0}, upper = {110.0, 140.0}, nominal = {100.0, 125.0};
  w.write("/bands/level_db", {2, 2}, level.data(), "dB");
  w.write("/bands/ci_lower_db", {2, 2}, level.data(), "dB");
  w.write("/bands/ci_upper_db", {2, 2}, level.data(), "dB");
  w.write("/bands/std", {2, 2}, one.data(), "1");
  w.write("/bands/log_std", {2, 2}, zero.data(), "1");
  w.write("/bands/lower_frequency", {2}, lower.data(), "Hz");
  w.write("/bands/upper_frequency", {2}, upper.data(), "Hz");
  w.write("/bands/nominal_frequency", {2}, nominal.data(), "Hz");
  w.write_strings("/bands/sensor", {"sensor_1", "sensor_2"});
  w.write("/psd/x", {1}, one.data(), "1");
  w.attribute("/psd", "realisations", static_cast<std::int64_t>(8));
  w.attribute("/psd", "confidence_level", 0.95);
  w.attribute("/psd", "interval_method", std::string("test"));
  w.commit();
}

}  // namespace

TEST_CASE("sweep point: a crossed sweep's bands read at a point by number and by value") {
  const fs::path dir = test::fresh_directory("rollspec_test_sweep_point");
  io::StackRequest q;
  for (int i = 0; i < 6; ++i) {
    q.inputs.push_back((dir / ("p" + std::to_string(i) + ".h5")).string());
    write_point(q.inputs.back(), i);
  }
  q.axes = {{"ball_speed", "m/s", "swept study key ball.speed", {1.0, 3.0}, {"1", "3"}},
            {"ball_radius", "m", "swept study key ball.radius", {0.01, 0.02, 0.03}, {"0.01", "0.02", "0.03"}}};
  q.mode = "crossed";
  q.study_text = "[study]\n";
  const std::string out = (dir / "sweep.h5").string();
  io::stack_results(q, out);
  const io::Hdf5Reader r(out);

  // Run order: the last key varies fastest, so point 5 is speed 3, radius 0.02.
  const auto by_number = io::read_band_levels(r, {"2", std::nullopt}, "5");
  CHECK(by_number.point == "ball.speed=3, ball.radius=0.02");
  CHECK(by_number.level_db == std::vector<double>{410.0, 411.0});
  const auto by_value = io::read_band_levels(r, {"1", std::nullopt}, "ball.radius=0.03,ball.speed=1");
  CHECK(by_value.level_db == std::vector<double>{200.0, 201.0});
  CHECK(io::read_band_levels(r, {"", std::nullopt}, "ball_speed=3.0, ball_radius=1e-2").level_db ==
        std::vector<double>{300.0, 301.0});

  // A sweep result without a point, a point out of range, a value that is no point, a key missing.
  for (const std::string bad : {"", "0", "7", "ball.speed=2,ball.radius=0.01", "ball.speed=1", "ball.mass=1"}) {
    CAPTURE(bad);
    try {
      io::read_band_levels(r, {"", std::nullopt}, bad);
      FAIL("accepted");
    } catch (const UserError& e) {
      CHECK(e.exit_code() == 64);
      CHECK(std::string(e.what()).find("6 points (crossed: ball.speed = 1, 3 x ball.radius = 0.01, 0.02, 0.03)") !=
            std::string::npos);
    }
  }
  // A result that is no sweep reads as before, and refuses a point.
  const io::Hdf5Reader plain(q.inputs[1]);
  CHECK(io::read_band_levels(plain, {"1", std::nullopt}).level_db == std::vector<double>{100.0, 101.0});
  CHECK_THROWS_AS(io::read_band_levels(plain, {"1", std::nullopt}, "1"), UserError);
  fs::remove_all(dir);
}
