// rollspec compare: a result's third-octave band levels against a measurement (design §7, "the verdict
// has two ends"). The options are read into a compare::CompareRequest; the engine's compare_result
// (src/compare/comparison.hpp) computes the whole verdict before anything is printed, so a refused input
// leaves no partial output; this file prints it as a table, CSV or JSON (src/compare/comparison_json.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/compare/comparison.hpp"
#include "src/compare/comparison_json.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

namespace {

using io::number_text;

const char* const kCompareUsage =
    "usage: rollspec compare RESULT.h5 MEASUREMENT... [--sensor NAME|K | --measured-position X] [--column NAME]...\n"
    "                        [--unit U] [--scale X] [--fs HZ] [--time-column NAME|none] [--skip-rows N]\n"
    "                        [--roll-per-channel] [--measured-averages M] [--noise QUIET] [--noise-margin DB]\n"
    "                        [--keep-floor-bands] [--same-surface] [--fmin HZ] [--fmax HZ] [--test-level A]\n"
    "                        [--point K|section.key=value] [--format table|csv|json]\n"
    "\n"
    "MEASUREMENT is either the recordings themselves (CSV/text, WAV/FLAC/..., .mat, read as `rollspec psd` reads\n"
    "them: units from the file, each choice said in one line), one file per roll, or one PSD table\n"
    "(frequency_hz and a one-sided PSD column in (m/s^2)^2/Hz, e.g. the output of `rollspec psd`).\n"
    "Recordings go through the model's own estimator (its Welch segment in seconds, window, overlap and\n"
    "detrending), so their bands average the model's bins and M, the number of rolls, is known: one file is\n"
    "one roll whose channels are the result's sensors (averaged for sensor_mean); --roll-per-channel takes\n"
    "each channel for a roll of one sensor. --measured-averages M gives M for a PSD table (or overrides it).\n"
    "\n"
    "For every third-octave band of the result inside [fmin, fmax] that the measurement covers it prints the\n"
    "simulated and measured band levels (dB re 1 (m/s^2)^2/Hz), their difference, the interval of the\n"
    "simulated mean and, with M, the prediction interval for a measurement of M rolls. Where the model's\n"
    "contact law is a random table (a stiffness, blocked-force or equivalent-roughness table), the question\n"
    "is a rig with another surface of this roughness: the table's own error enters twice, the model's table\n"
    "and the rig's surface (kernels/spectral D-31); --same-surface asks of the very surface the table was\n"
    "built on. `combined_test:` is one test over the tested bands (D-26, D-31), `level_offset:` the one level\n"
    "by which the model differs from the measurement over them with its interval (D-34).\n"
    "Bands near the noise floor leave the test and the offset and are shown apart: with --noise QUIET (a\n"
    "recording of the rig at rest, or its PSD), those within --noise-margin DB (default 10) of it, the others\n"
    "compared with the model plus that noise, its scatter included (D-33c); without, those where the\n"
    "measurement stays flat at its lowest level while the model falls far below (D-33b; --keep-floor-bands\n"
    "keeps them). A likely unit slip (every band off by 19.8 dB or 60 dB) and a PSD table on\n"
    "coarser bins than the model's (with by how many dB that moves its bands) are flagged.\n"
    "--format csv writes the table only (numeric columns; the summary goes to stderr), json everything.\n"
    "--measured-position X (m) compares the sensor nearest X (within half the sensors' smallest spacing).\n"
    "--point picks one point of a sweep result (its number K in run order, or its swept values).\n"
    "A result whose ball lost contact (more than 5 % of the time, or at all with law = linearised) is flagged.";

// A CSV cell: every bit of the number, empty where there is none (no interval, no noise recording).
std::string cell(double v) { return std::isfinite(v) ? io::exact_text(v) : ""; }

std::string offset_line(const compare::Verdict& v, double confidence) {
  if (!v.offset) return "";
  return io::formatted(
      "level_offset: model - measurement %+.2f dB, %d %% interval %+.2f .. %+.2f dB over %d tested bands "
      "(kernels/spectral D-34)\n",
      v.offset->estimate, static_cast<int>(std::lround(100.0 * confidence)), v.offset->lower, v.offset->upper,
      v.tested);
}

// --format csv: the band table only (one header line), for pandas and numpy's readers.
std::string csv_text(const compare::Verdict& v, bool predict, bool has_interval) {
  std::string text =
      "centre_hz,simulated_db,measured_db,delta_db,ci_lower_db,ci_upper_db,prediction_lower_db,"
      "prediction_upper_db,noise_db,use,inside\n";
  for (const auto& x : v.rows) {
    const bool in = predict ? x.inside_prediction : x.inside_ci;
    text += number_text(x.centre) + "," + cell(x.simulated) + "," + cell(x.measured) + "," + cell(x.delta) + "," +
            cell(x.ci_lower) + "," + cell(x.ci_upper) + "," + cell(x.pred_lower) + "," + cell(x.pred_upper) + "," +
            cell(x.noise) + "," + compare::band_use_name(x.use) + "," + (has_interval ? (in ? "1" : "0") : "") + "\n";
  }
  return text;
}

// --format table: the question, a row per band, the warnings, the level offset and the combined test.
std::string table_text(const compare::Verdict& v, const io::BandLevels& b, bool predict, bool has_interval) {
  std::string text = "question: " + v.question + "\n";
  text += io::formatted("%10s %12s %12s %8s %17s %17s %7s\n", "centre_Hz", "simulated_dB", "measured_dB", "delta_dB",
                        "mean_interval_dB", predict ? "prediction_dB" : "", "inside");
  for (const auto& x : v.rows) {
    const bool in = predict ? x.inside_prediction : x.inside_ci;
    const std::string ci = io::formatted("%7.2f..%-7.2f", x.ci_lower, x.ci_upper);
    const std::string pi = predict ? io::formatted("%7.2f..%-7.2f", x.pred_lower, x.pred_upper) : std::string();
    const std::string mark = x.use != compare::BandUse::test ? compare::band_use_name(x.use)
                             : has_interval                  ? (in ? "yes" : "no")
                                                             : "-";
    text += io::formatted("%10g %12.2f %12.2f %8.2f %17s %17s %7s\n", x.centre, x.simulated, x.measured, x.delta,
                          ci.c_str(), pi.c_str(), mark.c_str());
  }
  for (const auto& w : v.warnings) text += "WARNING: " + w + "\n";
  text += offset_line(v, b.confidence);
  if (predict) text += "combined_test: " + v.test.verdict + "\n";
  return text + io::formatted("rms_db_error: %.3f  inside_ci: %d/%d\n", v.rms_db, v.inside, v.judged);
}

}  // namespace

int compare_command(const Args& args) {
  const std::string usage = kCompareUsage;
  po::options_description opts("options");
  std::string format = "table";
  compare::CompareRequest q;
  double measured_position = NAN, records = 0.0, scale = 1.0, fs = 0.0;
  long long skip_rows = -1;
  opts.add_options()("result", po::value(&q.result)->required(), "result file (HDF5)")(
      "measurement", po::value(&q.measurements)->required()->multitoken(),
      "recordings (one file per roll) or one PSD table")(
      "sensor", po::value(&q.sensor),
      "sensor name, or the number K of sensor_K (1-based; default: sensor_mean if present, else the first)")(
      "measured-position", po::value(&measured_position),
      "where the measurement was taken (m): the sensor nearest it, within half the sensors' smallest spacing")(
      "column", po::value(&q.columns)->composing(),
      "channel(s) of the recordings, or the PSD column of a PSD table (default: every channel; psd)")(
      "unit", po::value(&q.unit), "unit of the recordings' values (default: from the file; m/s2, g, mm/s2, ...)")(
      "scale", po::value(&scale), "physical units per file unit, or per full scale (integer PCM)")(
      "fs", po::value(&fs), "sample rate of the recordings (Hz; default: from the file)")(
      "time-column", po::value(&q.time_column), "time column of CSV recordings, or none")(
      "skip-rows", po::value(&skip_rows), "CSV lines before the header (default: found from the data)")(
      "roll-per-channel", "each channel of the recordings is one roll of one sensor")(
      "measured-averages", po::value(&records), "M, independent rolls averaged into the measurement (>= 1)")(
      "noise", po::value(&q.noise), "a recording of the rig at rest (or its PSD table): its floor leaves the test")(
      "noise-margin", po::value(&q.noise_margin_db)->default_value(10.0, "10"),
      "bands within this many dB of the noise leave the test")(
      "keep-floor-bands", "keep the bands that look like the noise floor (no --noise) in the test")(
      "same-surface", "the measurement was taken on the very surface the model's table was built on (D-31)")(
      "fmin", po::value(&q.fmin)->default_value(0.0, "0"), "lowest band edge (Hz)")(
      "fmax", po::value(&q.fmax)->default_value(INFINITY, "inf"), "highest band edge (Hz)")(
      "point", po::value(&q.point), "the point of a sweep result: K (in run order) or section.key=value[,...]")(
      "format", po::value(&format)->default_value("table"), "table, csv or json")(
      "test-level", po::value(&q.test_level)->default_value(0.05, "0.05"), "level of the combined test (0 < A < 1)");
  po::positional_options_description pos;
  pos.add("result", 1).add("measurement", -1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (format != "table" && format != "csv" && format != "json")
    throw usage_error("--format " + format.substr(0, 200) + ": allowed: table, csv or json");
  if (vm.count("measured-position")) q.measured_position = measured_position;
  if (vm.count("measured-averages")) q.measured_averages = records;
  if (vm.count("scale")) q.scale = scale;
  if (vm.count("fs")) q.fs = fs;
  if (vm.count("skip-rows")) q.skip_rows = skip_rows;
  q.roll_per_channel = vm.count("roll-per-channel") > 0;
  q.keep_floor_bands = vm.count("keep-floor-bands") > 0;
  q.same_surface = vm.count("same-surface") > 0;
  q.reading_note = [](const std::string& note) { std::cerr << "rollspec compare: " << note << "\n"; };
  const compare::Comparison c = compare::compare_result(q);

  // Printed only once everything is computed: a refused input leaves no partial output.
  for (const auto& line : c.messages) std::cerr << "rollspec compare: " << line << "\n";
  if (format == "json") {
    std::cout << compare::comparison_json(c).dump(2) << "\n";
    return 0;
  }
  const compare::Verdict& v = c.verdict;
  const io::BandLevels& b = c.bands;
  const compare::MeasuredSpectrum& m = c.measurement;
  if (format == "csv") {
    std::fputs(csv_text(v, c.predict, c.has_interval).c_str(), stdout);
    std::cerr << "rollspec compare: question: " << v.question << "\n" << offset_line(v, b.confidence);
    if (c.predict) std::cerr << "combined_test: " << v.test.verdict << "\n";
    return 0;
  }
  std::string text = "result " + c.result + " (" + std::to_string(b.realisations) + " realisations), sensor " +
                     b.sensor + "; measurement " + m.source +
                     (c.psd_table ? ", column " + (c.column.empty() ? std::string("psd") : c.column) : "") +
                     (m.records_source.empty() ? "" : " (" + m.records_source + ")") + "\n";
  if (!c.loss.warning.empty()) text += "WARNING: " + c.loss.warning + "\n";
  if (!c.loss.note.empty()) text += "note: " + c.loss.note + "\n";
  text += table_text(v, b, c.predict, c.has_interval);
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
