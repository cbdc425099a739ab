// The PSD CSV and its CSVW sidecar (src/io/psd_csv.hpp): what write_psd_csv writes, read_psd_csv
// gives back with its metadata; a CSV edited afterwards keeps its numbers but loses the metadata (said),
// and is no longer one rollspec may replace; units in names and titles (measurement_unit.hpp).
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/measurement_unit.hpp"
#include "src/io/psd_csv.hpp"

namespace fs = std::filesystem;
using namespace rollspec::io;

namespace {
fs::path fresh_dir(const char* name) {
  const fs::path dir = fs::temp_directory_path() / (std::string(name) + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

PsdCsvMetadata metadata() {
  PsdCsvMetadata m;
  m.sample_rate = 1024.0;
  m.rate_source = "time column 'time_s'";
  m.segment = 256;
  m.overlap = 128;
  m.window = "hann";
  m.detrend = "mean";
  m.samples = 4096;
  m.segments = 31;
  m.edof = 58.8;
  m.source = "logger.csv";
  m.source_hash = "ab12";
  m.version = "test";
  return m;
}
}  // namespace

TEST_CASE("psd csv: written with its sidecar, read back with the metadata of the column asked for") {
  const fs::path dir = fresh_dir("rollspec_test_psd_csv");
  const std::string out = (dir / "m.csv").string();
  const auto titles = psd_column_titles({"Acc (g)", "b [m/s^2]", "c #1"});
  REQUIRE(titles.size() == 3);
  CHECK(titles[0] == "Acc [(m/s^2)^2/Hz]");
  CHECK(titles[1] == "b [(m/s^2)^2/Hz]");
  CHECK(titles[2] == "c _1 [(m/s^2)^2/Hz]");
  const std::string csv = "frequency_hz," + titles[0] + "," + titles[1] + "," + titles[2] + "\n0,1,2,3\n4,5,6,7\n";
  const std::vector<PsdColumnMetadata> columns{{titles[0], "Acc", "Acc (g)", "g", "its name"},
                                               {titles[1], "b", "b [m/s^2]", "m/s^2", "its name"},
                                               {titles[2], "c _1", "c #1", "m/s^2", "assumed"}};
  write_psd_csv(out, false, {}, csv, metadata(), columns);
  CHECK(psd_csv_written_by_rollspec(out));

  const PsdCsv byname = read_psd_csv(out, "Acc", -1);
  CHECK(byname.column == titles[0]);
  CHECK(byname.psd == std::vector<double>{1, 5});
  REQUIRE(byname.metadata);
  CHECK(byname.metadata->segment == 256);
  CHECK(byname.metadata->edof == doctest::Approx(58.8));
  CHECK(byname.metadata->source == "logger.csv");
  CHECK(byname.metadata->column.channel == "Acc (g)");
  CHECK(byname.metadata->column.signal_unit == "g");
  CHECK(read_psd_csv(out, "b [m/s^2]", -1).psd == std::vector<double>{2, 6});  // the channel's own name
  try {
    read_psd_csv(out, "", -1);
    FAIL("three PSD columns and no column were read");
  } catch (const rollspec::UserError& e) {
    CHECK(e.exit_code() == 64);
    CHECK(std::string(e.what()).find("3 PSD columns (Acc, b, c _1") != std::string::npos);
    CHECK(std::string(e.what()).find("--column NAME") != std::string::npos);
  }

  // edited: same numbers read, the metadata ignored with a note, and no longer rollspec's to replace
  std::ofstream(out, std::ios::app) << "8,9,10,11\n";
  const PsdCsv edited = read_psd_csv(out, "Acc", -1);
  CHECK(!edited.metadata);
  CHECK(edited.psd == std::vector<double>{1, 5, 9});
  REQUIRE(!edited.notes.empty());
  CHECK(edited.notes[0].find("m.csv-metadata.json is ignored: it records another SHA-256") != std::string::npos);
  CHECK(!psd_csv_written_by_rollspec(out));
  CHECK_THROWS_AS(write_psd_csv(out, false, {}, csv, metadata(), columns), rollspec::UserError);
  write_psd_csv(out, true, {}, csv, metadata(), columns);  // --force
  CHECK(psd_csv_written_by_rollspec(out));
  fs::remove_all(dir);
}

TEST_CASE("measurement units: names, units rows and PSD titles") {
  CHECK(unit_in_name("Acc (g)").unit->text == "g");
  CHECK(unit_in_name("Acc (g)").base == "Acc");
  CHECK(unit_in_name("a [m/s\xC2\xB2]").unit->text == "m/s^2");
  CHECK(unit_in_name("acc [mm/s^2]").unit->factor == doctest::Approx(1e-3));
  CHECK(unit_in_name("a/(m/s^2)").base == "a");
  CHECK(unit_in_name("t [\xC2\xB5s]").unit->factor == doctest::Approx(1e-6));
  CHECK(unit_in_name("zeit_ms").unit->factor == doctest::Approx(1e-3));
  CHECK(unit_in_name("in/s2 [in/s\xB2]").unit->factor == doctest::Approx(0.0254));  // ISO-8859-1 superscript
  CHECK(!unit_in_name("pair_1").unit);
  CHECK(!unit_in_name("acc (sensor 2)").unit);
  CHECK(unit_in_name("acc (sensor 2)").base == "acc (sensor 2)");
  CHECK(unit_in_name("F [N]").unit->quantity == Quantity::other);
  CHECK(parse_measurement_unit("m s^-2")->text == "m/s^2");
  CHECK(parse_measurement_unit("ft/s/s")->factor == doctest::Approx(0.3048));
  CHECK(!parse_measurement_unit("mg"));
  CHECK(parse_psd_unit("g^2/Hz")->factor == doctest::Approx(9.80665 * 9.80665));
  CHECK(parse_psd_unit("(m/s^2)^2/Hz")->factor == 1.0);
  CHECK(parse_psd_unit("(mm/s\xC2\xB2)\xC2\xB2/Hz")->factor == doctest::Approx(1e-6));
  CHECK(!parse_psd_unit("dB/Hz"));
}
