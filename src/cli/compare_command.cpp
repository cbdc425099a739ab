// rollspec compare: a result's third-octave band levels against a measurement (design §7, "the verdict
// has two ends"). The measurement is the recordings themselves (put through the model's own estimator,
// src/compare/measured_spectrum.hpp) or a PSD table; the verdict (src/compare/band_verdict.hpp) is
// computed whole before anything is printed, so a refused input leaves no partial output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/cli/commands.hpp"
#include "src/compare/measured_psd.hpp"
#include "src/cli/parse_options.hpp"
#include "src/compare/band_verdict.hpp"
#include "src/compare/verdict_references.hpp"
#include "src/compare/measured_spectrum.hpp"
#include "src/error.hpp"
#include "src/io/band_levels.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/references.hpp"
#include "src/io/sweep_point.hpp"

namespace rollspec::cli {

using compare::Measurement;
using compare::read_measurement;

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

// The result's loss of contact (ball-on-beam): its share and the warning `run` wrote.
struct LossOfContact {
  double share = NAN;
  std::string warning, note;  // a warning where it moved bands (D-35), else a note of its share
};

LossOfContact loss_of_contact(const io::Hdf5Reader& r, const io::SweepPoint& at) {
  LossOfContact l;
  if (r.exists("/contact/loss_of_contact_share"))
    l.share = io::read_at_point(r, at, "/contact/loss_of_contact_share", 1).at(0);
  if (r.exists("/contact") && r.has_attribute("/contact", "loss_of_contact_warning"))
    l.warning = r.string_attribute("/contact", "loss_of_contact_warning");
  if (r.exists("/contact") && r.has_attribute("/contact", "loss_of_contact_note"))
    l.note = r.string_attribute("/contact", "loss_of_contact_note");
  return l;
}

// The row's mean PSD and bin width (the resolution check); empty when the result lacks them.
std::vector<double> mean_psd_row(const io::Hdf5Reader& r, const io::SweepPoint& at, const std::string& sensor,
                                 double& df) {
  if (!r.exists("/psd/mean") || !r.exists("/psd/sensor") || !r.exists("/psd/frequency")) return {};
  const auto names = r.read_strings("/psd/sensor");
  const auto f = r.read("/psd/frequency"), mean = io::read_at_point(r, at, "/psd/mean", 2);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == sensor && f.size() >= 2 && mean.size() == names.size() * f.size() && f[0] == 0.0) {
      df = f[1] - f[0];
      return {mean.begin() + static_cast<std::ptrdiff_t>(i * f.size()),
              mean.begin() + static_cast<std::ptrdiff_t>((i + 1) * f.size())};
    }
  return {};
}

// A PSD table as the measurement: on the model's grid when its points are the model's bins.
compare::MeasuredSpectrum psd_table(const std::string& path, std::string& column, long long skip_rows, double df) {
  const Measurement t = read_measurement(path, column, skip_rows, "compare");
  compare::MeasuredSpectrum m;
  m.source = path;
  m.frequency = t.frequency;
  m.psd = t.psd;
  bool grid = df > 0.0 && m.frequency.size() >= 2 && m.frequency[0] == 0.0;
  for (std::size_t k = 0; grid && k < m.frequency.size(); ++k)
    grid = std::fabs(m.frequency[k] - static_cast<double>(k) * df) <= 1e-9 * df * static_cast<double>(k + 1);
  m.model_grid = grid;
  return m;
}

std::size_t sensors_in_row(const io::Hdf5Reader& r, const std::string& row) {
  if (row != "sensor_mean") return 1;
  std::size_t n = 0;
  for (const auto& name : r.read_strings("/bands/sensor")) n += name != "sensor_mean";
  return n;
}

// A CSV cell: every bit of the number, empty where there is none (no interval, no noise recording).
std::string cell(double v) { return std::isfinite(v) ? io::exact_text(v) : ""; }

nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

// A spectrum as drawn (python-post's report plots it): the measurement through the model's estimator, or
// the PSD table as read; null without one.
nlohmann::ordered_json spectrum_json(const compare::MeasuredSpectrum* m) {
  if (!m) return nullptr;
  return {{"frequency_hz", m->frequency}, {"psd", m->psd}, {"units", "(m/s^2)^2/Hz"}, {"model_bins", m->model_grid}};
}

nlohmann::ordered_json verdict_json(const std::string& result, const std::string& column, const io::BandLevels& b,
                                    const compare::MeasuredSpectrum& m, const compare::MeasuredSpectrum* noise,
                                    const compare::Verdict& v, const LossOfContact& loss,
                                    const nlohmann::ordered_json& references) {
  using json = nlohmann::ordered_json;
  const bool predict = m.records > 0.0;
  const bool has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  json bands = json::array();
  for (const auto& r : v.rows)
    bands.push_back({{"centre_hz", r.centre},
                     {"lower_hz", b.lower[r.band]},
                     {"upper_hz", b.upper[r.band]},
                     {"simulated_db", number(r.simulated)},
                     {"measured_db", number(r.measured)},
                     {"delta_db", number(r.delta)},
                     {"ci_lower_db", number(r.ci_lower)},
                     {"ci_upper_db", number(r.ci_upper)},
                     {"prediction_lower_db", number(r.pred_lower)},
                     {"prediction_upper_db", number(r.pred_upper)},
                     {"noise_db", number(r.noise)},
                     {"use", compare::band_use_name(r.use)},
                     {"inside", has_interval ? json(predict ? r.inside_prediction : r.inside_ci) : json(nullptr)}});
  const auto& t = v.test.result;
  json offset = nullptr;
  if (v.offset)
    offset = {{"estimate_db", v.offset->estimate},
              {"lower_db", v.offset->lower},
              {"upper_db", v.offset->upper},
              {"dof", v.offset->dof},
              {"bands", v.tested},
              {"method", "weighted least squares, each band by its own variance (kernels/spectral D-34)"}};
  return {
      {"result", result},
      {"sensor", b.sensor},
      {"measurement", m.source},
      {"column", column.empty() ? json(nullptr) : json(column)},
      {"realisations", b.realisations},
      {"confidence_level", b.confidence},
      {"interval_method", b.interval_method},
      {"measured_averages", predict ? json(m.records) : json(nullptr)},
      {"measured_averages_source", m.records_source},
      {"measurement_notes", m.notes},
      {"table_term",
       {{"factor", v.table_factor},
        {"table", b.table.empty() ? json(nullptr) : json(b.table)},
        {"units", b.table_units},
        {"dof", number(b.table_dof)},
        {"estimated", b.table_units >= 2}}},
      {"loss_of_contact_share", number(loss.share)},
      {"loss_of_contact_warning", loss.warning.empty() ? json(nullptr) : json(loss.warning)},
      {"loss_of_contact_note", loss.note.empty() ? json(nullptr) : json(loss.note)},
      {"question", v.question},
      {"bands", bands},
      {"rms_db_error", number(v.rms_db)},
      {"inside", has_interval ? v.inside : 0},
      {"judged", v.judged},
      {"bands_compared", v.rows.size()},
      {"bands_tested", v.tested},
      {"level_offset", offset},
      {"warnings", v.warnings},
      {"p_value", t.defined ? json(t.p_value) : json(nullptr)},
      {"combined_test",
       {{"method", t.draws > 0 ? "Hotelling T2, law by parametric bootstrap with the table term (kernels/spectral D-31)"
                               : "Hotelling T2, F law (kernels/spectral D-26)"},
        {"level", v.test.level},
        {"defined", t.defined},
        {"rejected", t.defined ? json(v.test.rejected) : json(nullptr)},
        {"t2", t.defined ? json(t.t2) : json(nullptr)},
        {"f", t.defined && t.draws == 0 ? json(t.f) : json(nullptr)},
        {"dof", t.defined && t.draws == 0 ? json::array({t.dof1, t.dof2}) : json(nullptr)},
        {"bootstrap_draws", t.draws},
        {"bands", v.test.bands},
        {"verdict", v.test.verdict}}},
      {"measured_psd", spectrum_json(&m)},
      {"noise_psd", spectrum_json(noise)},
      {"references", references}};
}

// The result's references (its /provenance/references) then the verdict's own, each once: {id, citation, doi}.
nlohmann::ordered_json references_json(const io::Hdf5Reader& r, const std::vector<std::string>& verdict_ids) {
  std::vector<std::string> lines = io::read_reference_lines(r);
  for (const auto& line : io::reference_lines(verdict_ids))
    if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& line : lines) {
    const std::size_t a = line.find(" | "), b = line.rfind(" | ");
    if (a == std::string::npos || b == a) continue;  // not a reference line: nothing to quote
    out.push_back(
        {{"id", line.substr(0, a)}, {"citation", line.substr(a + 3, b - a - 3)}, {"doi", line.substr(b + 3)}});
  }
  return out;
}

std::string offset_line(const compare::Verdict& v, double confidence) {
  if (!v.offset) return "";
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "level_offset: model - measurement %+.2f dB, %d %% interval %+.2f .. %+.2f dB over %d tested bands "
                "(kernels/spectral D-34)\n",
                v.offset->estimate, static_cast<int>(std::lround(100.0 * confidence)), v.offset->lower, v.offset->upper,
                v.tested);
  return buf;
}

// Every option's value checked before any file is read.
void check_options(const std::string& format, const compare::VerdictOptions& o, const po::variables_map& vm,
                   double records, const io::SignalRequest& signal) {
  if (format != "table" && format != "csv" && format != "json")
    throw usage_error("--format " + format.substr(0, 200) + ": allowed: table, csv or json");
  if (!(o.fmin >= 0.0) || std::isinf(o.fmin))
    throw usage_error("--fmin " + number_text(o.fmin) + ": allowed: a finite frequency >= 0 Hz");
  if (!(o.fmax > o.fmin))
    throw usage_error("--fmax " + number_text(o.fmax) + ": allowed: a frequency above --fmin (" + number_text(o.fmin) +
                      " Hz)");
  if (!(o.test_level > 0.0 && o.test_level < 1.0))
    throw usage_error("--test-level " + number_text(o.test_level) + ": allowed: a level 0 < A < 1, e.g. 0.05");
  if (!(o.noise_margin_db >= 0.0 && std::isfinite(o.noise_margin_db)))
    throw usage_error("--noise-margin " + number_text(o.noise_margin_db) + ": allowed: a finite margin >= 0 dB");
  if (vm.count("measured-averages") && !(records >= 1.0 && std::isfinite(records)))
    throw usage_error("--measured-averages " + number_text(records) +
                      ": allowed: a finite count >= 1 of independent rolls");
  if (vm.count("skip-rows") && signal.skip_rows < 0)
    throw usage_error("--skip-rows " + std::to_string(signal.skip_rows) +
                      ": allowed: a whole number >= 0 (lines before the header)");
  if (vm.count("fs") && !(signal.fs > 0.0 && std::isfinite(signal.fs)))
    throw usage_error("--fs " + number_text(signal.fs) + ": allowed: a finite sample rate > 0 Hz");
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
std::string table_text(const compare::Verdict& v, const io::BandLevels& b, bool predict) {
  const bool has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  std::string text = "question: " + v.question + "\n";
  char buf[320];
  std::snprintf(buf, sizeof buf, "%10s %12s %12s %8s %17s %17s %7s\n", "centre_Hz", "simulated_dB", "measured_dB",
                "delta_dB", "mean_interval_dB", predict ? "prediction_dB" : "", "inside");
  text += buf;
  for (const auto& x : v.rows) {
    const bool in = predict ? x.inside_prediction : x.inside_ci;
    char ci[40] = "", pi[40] = "";
    std::snprintf(ci, sizeof ci, "%7.2f..%-7.2f", x.ci_lower, x.ci_upper);
    if (predict) std::snprintf(pi, sizeof pi, "%7.2f..%-7.2f", x.pred_lower, x.pred_upper);
    const std::string mark = x.use != compare::BandUse::test ? compare::band_use_name(x.use)
                             : has_interval                  ? (in ? "yes" : "no")
                                                             : "-";
    std::snprintf(buf, sizeof buf, "%10g %12.2f %12.2f %8.2f %17s %17s %7s\n", x.centre, x.simulated, x.measured,
                  x.delta, ci, pi, mark.c_str());
    text += buf;
  }
  for (const auto& w : v.warnings) text += "WARNING: " + w + "\n";
  text += offset_line(v, b.confidence);
  if (predict) text += "combined_test: " + v.test.verdict + "\n";
  std::snprintf(buf, sizeof buf, "rms_db_error: %.3f  inside_ci: %d/%d\n", v.rms_db, v.inside, v.judged);
  return text + buf;
}

}  // namespace

int compare_command(const Args& args) {
  const std::string usage = kCompareUsage;
  po::options_description opts("options");
  std::string result, format = "table", sensor, noise, point;
  std::vector<std::string> measurements;
  io::SignalRequest signal;
  double measured_position = NAN, records = 0.0;
  compare::VerdictOptions o;
  opts.add_options()("result", po::value(&result)->required(), "result file (HDF5)")(
      "measurement", po::value(&measurements)->required()->multitoken(),
      "recordings (one file per roll) or one PSD table")(
      "sensor", po::value(&sensor),
      "sensor name, or the number K of sensor_K (1-based; default: sensor_mean if present, else the first)")(
      "measured-position", po::value(&measured_position),
      "where the measurement was taken (m): the sensor nearest it, within half the sensors' smallest spacing")(
      "column", po::value(&signal.columns)->composing(),
      "channel(s) of the recordings, or the PSD column of a PSD table (default: every channel; psd)")(
      "unit", po::value(&signal.unit), "unit of the recordings' values (default: from the file; m/s2, g, mm/s2, ...)")(
      "scale", po::value(&signal.scale), "physical units per file unit, or per full scale (integer PCM)")(
      "fs", po::value(&signal.fs), "sample rate of the recordings (Hz; default: from the file)")(
      "time-column", po::value(&signal.time_column), "time column of CSV recordings, or none")(
      "skip-rows", po::value(&signal.skip_rows), "CSV lines before the header (default: found from the data)")(
      "roll-per-channel", "each channel of the recordings is one roll of one sensor")(
      "measured-averages", po::value(&records), "M, independent rolls averaged into the measurement (>= 1)")(
      "noise", po::value(&noise), "a recording of the rig at rest (or its PSD table): its floor leaves the test")(
      "noise-margin", po::value(&o.noise_margin_db)->default_value(10.0, "10"),
      "bands within this many dB of the noise leave the test")(
      "keep-floor-bands", "keep the bands that look like the noise floor (no --noise) in the test")(
      "same-surface", "the measurement was taken on the very surface the model's table was built on (D-31)")(
      "fmin", po::value(&o.fmin)->default_value(0.0, "0"), "lowest band edge (Hz)")(
      "fmax", po::value(&o.fmax)->default_value(INFINITY, "inf"), "highest band edge (Hz)")(
      "point", po::value(&point), "the point of a sweep result: K (in run order) or section.key=value[,...]")(
      "format", po::value(&format)->default_value("table"), "table, csv or json")(
      "test-level", po::value(&o.test_level)->default_value(0.05, "0.05"), "level of the combined test (0 < A < 1)");
  po::positional_options_description pos;
  pos.add("result", 1).add("measurement", -1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  check_options(format, o, vm, records, signal);
  signal.scale_given = vm.count("scale") > 0;
  o.same_surface = vm.count("same-surface") > 0;
  o.floor_check = vm.count("keep-floor-bands") == 0;

  for (const auto& path : measurements) {
    io::require_regular_input(path, "a measurement");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      throw missing_input("cannot read '" + path +
                          "': it is a directory; expected a recording (CSV/text, WAV/FLAC, .mat) or a PSD table (CSV)");
  }
  const io::SensorChoice choice = io::sensor_choice(
      sensor, vm.count("measured-position") ? std::optional<double>(measured_position) : std::nullopt);
  const io::Hdf5Reader r(result);
  io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
  const io::BandLevels b = io::read_band_levels(r, choice, point);
  const io::SweepPoint at = io::sweep_point(r, point);
  o.model_psd = mean_psd_row(r, at, b.sensor, o.model_df);

  // The measurement: one PSD table, or recordings through the model's estimator.
  const bool table = measurements.size() == 1 && compare::is_psd_table(measurements[0]);
  std::string column = signal.columns.size() == 1 ? signal.columns[0] : "";
  compare::MeasuredSpectrum m;
  const auto estimator = compare::read_model_estimator(r);
  compare::RecordingOptions ro;
  ro.signal = signal;
  ro.roll_per_channel = vm.count("roll-per-channel") > 0;
  ro.model_sensors = sensors_in_row(r, b.sensor);
  if (table) {
    if (signal.columns.size() > 1)
      throw usage_error("--column: " + std::to_string(signal.columns.size()) +
                        " columns for a PSD table; allowed: one PSD column");
    m = psd_table(measurements[0], column, signal.skip_rows, o.model_df);
  } else {
    if (!estimator)
      throw data_error(result +
                       ": has no record of its estimator (/psd@sample_rate, welch_segment, ...: written "
                       "by this rollspec); re-run the study, or give compare a PSD table of the recording");
    m = compare::measure_recordings(measurements, ro, *estimator);
  }
  if (vm.count("measured-averages")) {
    if (m.records > 0.0 && records != m.records)
      m.notes.push_back("--measured-averages " + number_text(records) + " replaces M = " + number_text(m.records) +
                        " (" + m.records_source + ")");
    m.records = records;
    m.records_source = "--measured-averages";
  }
  compare::MeasuredSpectrum quiet;
  if (!noise.empty()) {
    if (compare::is_psd_table(noise)) {
      std::string noise_column;
      quiet = psd_table(noise, noise_column, -1, o.model_df);
    } else {
      if (!estimator) throw data_error(result + ": has no record of its estimator; give --noise as a PSD table");
      quiet = compare::measure_recordings({noise}, ro, *estimator);
    }
    o.noise = &quiet;
  }
  const compare::Verdict v = compare::band_verdict(b, m, o);
  const LossOfContact loss = loss_of_contact(r, at);

  // Printed only once everything is computed: a refused input leaves no partial output.
  if (!b.pick_note.empty()) std::cerr << "rollspec compare: " << b.pick_note << "\n";
  for (const auto& note : m.notes) std::cerr << "rollspec compare: " << note << "\n";
  if (!loss.warning.empty()) std::cerr << "rollspec compare: WARNING: " << result << ": " << loss.warning << "\n";
  if (b.table_error_missing && !o.same_surface && m.records > 0.0)
    std::cerr << "rollspec compare: WARNING: " << result << ": its intervals are conditional on its " << b.table
              << " (the table's own error was not estimated: [stiffness] table_error = none), so this verdict leaves "
                 "that error out and holds only for the surface the table was built on\n";
  for (const auto& w : v.warnings) std::cerr << "rollspec compare: WARNING: " << w << "\n";
  if (format == "json") {
    const bool predict = m.records > 0.0 && b.realisations >= spectral::kMinRealisationsForInterval;
    const auto references = references_json(r, compare::verdict_references(v, !table, predict));
    std::cout << verdict_json(result, column, b, m, o.noise, v, loss, references).dump(2) << "\n";
    return 0;
  }
  const bool predict = m.records > 0.0 && b.realisations >= spectral::kMinRealisationsForInterval;
  if (format == "csv") {
    std::fputs(csv_text(v, predict, b.realisations >= spectral::kMinRealisationsForInterval).c_str(), stdout);
    std::cerr << "rollspec compare: question: " << v.question << "\n" << offset_line(v, b.confidence);
    if (predict) std::cerr << "combined_test: " << v.test.verdict << "\n";
    return 0;
  }
  std::string text = "result " + result + " (" + std::to_string(b.realisations) + " realisations), sensor " + b.sensor +
                     "; measurement " + m.source +
                     (table ? ", column " + (column.empty() ? std::string("psd") : column) : "") +
                     (m.records_source.empty() ? "" : " (" + m.records_source + ")") + "\n";
  if (!loss.warning.empty()) text += "WARNING: " + loss.warning + "\n";
  if (!loss.note.empty()) text += "note: " + loss.note + "\n";
  text += table_text(v, b, predict);
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
