// rollspec compare: simulated third-octave band levels against a measured PSD (design §7).
// Two questions, said in the output: is the measured level inside the interval of the simulated
// *mean* (the default), or, given --measured-averages M, inside the prediction interval of a
// measurement that averages M independent records (kernels/spectral D-22)?
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/ensemble_interval.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/compare_band_test.hpp"
#include "src/cli/measured_psd.hpp"
#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/band_levels.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"

namespace rollspec::cli {

namespace {

using io::number_text;

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\')
      out += '\\', out += static_cast<char>(c);
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else
      out += static_cast<char>(c);
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

struct BandRow {
  double centre, simulated, measured, delta, ci_lower, ci_upper, pred_lower, pred_upper;
  bool inside_ci, inside_prediction;
  std::size_t band;  // index in the result's bands
};

}  // namespace

const char* const kCompareUsage =
    "usage: rollspec compare RESULT.h5 MEASUREMENT.csv [--sensor NAME|K | --measured-position X] [--column NAME]\n"
    "                        [--measured-averages M] [--fmin HZ] [--fmax HZ] [--test-level A] [--format "
    "table|csv|json] [--skip-rows N]\n"
    "\n"
    "MEASUREMENT.csv holds frequency_hz and a one-sided PSD column in (m/s^2)^2/Hz: the one --column names,\n"
    "else `psd`, else in the output of `rollspec psd` of one channel its only PSD column (so it is read\n"
    "directly). For every third-octave band of the result inside [fmin, fmax] that the measurement covers,\n"
    "prints the simulated and measured band levels\n"
    "(dB re 1 (m/s^2)^2/Hz), their difference, the interval of the simulated mean and, with\n"
    "--measured-averages M (the number of independent records averaged into the measurement, e.g. rolls;\n"
    "sensors of one roll are not independent), the prediction interval for such a measurement. `inside`\n"
    "answers the question the output states. With --measured-averages M, `combined_test:` gives one test\n"
    "over all compared bands at once (kernels/spectral D-26: Hotelling T2 with the realisations'\n"
    "between-band covariance, F law): its p-value and verdict at --test-level A (default 0.05); a count of\n"
    "bands inside has no known law, this test has. The last line is `rms_db_error: X  inside_ci: Y/Z`.\n"
    "--format csv writes the table with numeric columns and the summary as `# ` lines (pandas: comment='#');\n"
    "--format json writes everything (the test as p_value, combined_test).\n"
    "Preamble lines before the measurement's header are skipped (said on stderr), as `rollspec psd` does;\n"
    "--skip-rows N: the header follows the first N lines.\n"
    "--measured-position X (m, where the measurement was taken) compares the sensor nearest X in the\n"
    "result's /bands/sensor_position, named on stderr with its position; refused if no sensor lies within\n"
    "half the smallest spacing between sensors (nothing nearer than the study resolves), or with --sensor.\n"
    "A result whose ball lost contact (more than 5 % of the time, or at all with law = linearised) is\n"
    "flagged: a `WARNING:` line before the table (`# WARNING:` in csv, on stderr too), and in json\n"
    "loss_of_contact_share and loss_of_contact_warning (null without).";

// The measurement's band average joins its points linearly, the result's band level sums its bins: a
// band of a bin or two beside a steep slope reads differently by the two. Measured on the result's own
// mean PSD, a difference above the band's standard deviation in a prediction interval (the mean's and
// a measurement of `records` records') decides the band by itself (kernels/spectral D-27h, as `fit`
// checks). One line naming every such band; nothing without --measured-averages, where the mean's own
// interval is narrower than any grid's rule.
void warn_band_rules(const io::Hdf5Reader& r, const io::BandLevels& b, const std::vector<BandRow>& rows,
                     double records) {
  if (!r.exists("/psd/mean") || !r.exists("/psd/sensor") || !r.exists("/psd/frequency")) return;
  const auto names = r.read_strings("/psd/sensor");
  const auto f = r.read("/psd/frequency"), mean = r.read("/psd/mean");
  const auto it = std::find(names.begin(), names.end(), b.sensor);
  if (it == names.end() || f.size() < 2 || mean.size() != names.size() * f.size() || f[0] != 0.0) return;
  const double* psd = mean.data() + static_cast<std::size_t>(it - names.begin()) * f.size();
  const double df = f[1] - f[0], K = static_cast<double>(b.realisations);
  std::string bands;
  int count = 0;
  for (const auto& row : rows) {
    const std::size_t k = row.band;
    const double s = b.log_std[k] * b.log_std[k];
    const double sd = std::sqrt(std::log1p(std::expm1(s) / K) + std::log1p(std::expm1(s) / records));
    const double shift = spectral::band_rule_shift(psd, f.size(), df, b.lower[k], b.upper[k]);
    if (!(sd > 0.0) || !(std::fabs(shift) > sd)) continue;
    char one[160];
    std::snprintf(one, sizeof one, "%s%.4g .. %.4g Hz (%.2g bins, %+.2f dB, %.2g sd)", count ? "; " : "", b.lower[k],
                  b.upper[k], (b.upper[k] - b.lower[k]) / df, 10.0 / std::log(10.0) * shift, std::fabs(shift) / sd);
    bands += one;
    ++count;
  }
  if (count == 0) return;
  std::fprintf(stderr,
               "rollspec compare: WARNING: %d band%s of the result's %.4g Hz grid read differently as the "
               "measurement is read (its points joined linearly) and as the result's band levels are (its bins), by "
               "more than the band's standard deviation, enough to decide the band by itself (kernels/spectral "
               "D-27h): %s; leave %s out (--fmin/--fmax) or refine the result's grid (spectrum.segment)\n",
               count, count == 1 ? "" : "s", df, bands.c_str(), count == 1 ? "it" : "them");
}

// The bands inside [fmin, fmax] that the measurement covers, with the simulated mean's interval
// and, for records > 0 (a measurement averaged over that many records), the prediction interval.
std::vector<BandRow> band_rows(const io::BandLevels& b, const Measurement& m, const std::string& measurement,
                               double fmin, double fmax, double records) {
  const bool predict = records > 0.0;
  const bool has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  std::vector<BandRow> rows;
  for (std::size_t k = 0; k < b.level_db.size(); ++k) {
    if (b.lower[k] < fmin || b.upper[k] > fmax) continue;
    if (m.frequency.size() < 2 || m.frequency.front() > b.lower[k] || m.frequency.back() < b.upper[k]) continue;
    const double meas =
        spectral::band_average_irregular(m.frequency.data(), m.psd.data(), m.frequency.size(), b.lower[k], b.upper[k]);
    if (!std::isfinite(meas))
      throw data_error(measurement + ": the measured PSD averaged over the band " + number_text(b.lower[k]) + " .. " +
                       number_text(b.upper[k]) +
                       " Hz is not finite (overflow); allowed: psd values whose band average is a finite double");
    if (meas <= 0.0) continue;
    BandRow row{};
    row.band = k;
    row.centre = b.nominal[k];
    row.simulated = b.level_db[k];
    row.measured = 10.0 * std::log10(meas);
    row.delta = row.simulated - row.measured;
    row.ci_lower = b.ci_lower_db[k];
    row.ci_upper = b.ci_upper_db[k];
    row.inside_ci = has_interval && row.measured >= row.ci_lower && row.measured <= row.ci_upper;
    row.pred_lower = row.pred_upper = NAN;
    if (predict && has_interval) {
      const double level = std::pow(10.0, row.simulated / 10.0);
      // The realisations' band averages: mean, spread, and the spread of their log (the level stands in
      // for the mean of the logs' law, which only needs the spread).
      const spectral::Scatter sc{level, b.std_dev[k], std::log(level), b.log_std[k]};
      const auto p = spectral::prediction_interval(sc, b.realisations, records, b.confidence);
      row.pred_lower = row.simulated + 10.0 * std::log10(p.lower);
      row.pred_upper = row.simulated + 10.0 * std::log10(p.upper);
      row.inside_prediction = row.measured >= row.pred_lower && row.measured <= row.pred_upper;
    }
    rows.push_back(row);
  }
  return rows;
}

// The result's loss of contact (ball-on-beam): its share and, above the threshold or with law =
// linearised, the warning `run` wrote; a comparison of such a result says so before anything else.
struct LossOfContact {
  double share = NAN;
  std::string warning;
};

LossOfContact loss_of_contact(const io::Hdf5Reader& r) {
  LossOfContact l;
  if (r.exists("/contact/loss_of_contact_share")) l.share = r.read("/contact/loss_of_contact_share").at(0);
  if (r.exists("/contact") && r.has_attribute("/contact", "loss_of_contact_warning"))
    l.warning = r.string_attribute("/contact", "loss_of_contact_warning");
  return l;
}

// What the printed forms of a comparison share.
struct Comparison {
  const std::string &result, &measurement, &column;
  const io::BandLevels& b;
  const std::vector<BandRow>& rows;
  bool predict;
  double records;
  bool has_interval;
  const std::string& question;
  double rms;
  int inside, judged;
  const CombinedTest& test;
  const LossOfContact& loss;
};

// `--format json`: one object with the inputs, the question, every band and the summary.
std::string json_text(const Comparison& c) {
  const auto& [result, measurement, column, b, rows, predict, records, has_interval, question, rms, inside, judged,
               test, loss] = c;
  std::string text;
  text += "{\n  \"result\": " + json_string(result) + ",\n  \"sensor\": " + json_string(b.sensor) +
          ",\n  \"measurement\": " + json_string(measurement) +
          ",\n  \"column\": " + json_string(column.empty() ? "psd" : column) +
          ",\n  \"realisations\": " + std::to_string(b.realisations) +
          ",\n  \"confidence_level\": " + json_number(b.confidence) +
          ",\n  \"interval_method\": " + json_string(b.interval_method) +
          ",\n  \"measured_averages\": " + (predict ? json_number(records) : "null") +
          ",\n  \"loss_of_contact_share\": " + json_number(loss.share) +
          ",\n  \"loss_of_contact_warning\": " + (loss.warning.empty() ? "null" : json_string(loss.warning)) +
          ",\n  \"question\": " + json_string(question) + ",\n  \"bands\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& x = rows[i];
    text += "    {\"centre_hz\": " + json_number(x.centre) + ", \"simulated_db\": " + json_number(x.simulated) +
            ", \"measured_db\": " + json_number(x.measured) + ", \"delta_db\": " + json_number(x.delta) +
            ", \"ci_lower_db\": " + json_number(x.ci_lower) + ", \"ci_upper_db\": " + json_number(x.ci_upper) +
            ", \"prediction_lower_db\": " + json_number(x.pred_lower) +
            ", \"prediction_upper_db\": " + json_number(x.pred_upper) + ", \"inside\": " +
            (!has_interval                                   ? "null"
             : (predict ? x.inside_prediction : x.inside_ci) ? "true"
                                                             : "false") +
            "}" + (i + 1 < rows.size() ? ",\n" : "\n");
  }
  text += "  ],\n  \"rms_db_error\": " + json_number(rms) +
          ",\n  \"inside\": " + std::to_string(has_interval ? inside : 0) +
          ",\n  \"judged\": " + std::to_string(judged) + ",\n  \"bands_compared\": " + std::to_string(rows.size()) +
          ",\n  \"p_value\": " + (test.result.defined ? json_number(test.result.p_value) : "null") +
          ",\n  \"combined_test\": {\"method\": \"Hotelling T2, F law (kernels/spectral D-26)\", \"level\": " +
          json_number(test.level) + ", \"defined\": " + (test.result.defined ? "true" : "false") +
          ", \"rejected\": " + (test.result.defined ? (test.rejected ? "true" : "false") : "null") +
          ", \"t2\": " + (test.result.defined ? json_number(test.result.t2) : "null") +
          ", \"f\": " + (test.result.defined ? json_number(test.result.f) : "null") + ", \"dof\": " +
          (test.result.defined ? "[" + json_number(test.result.dof1) + ", " + json_number(test.result.dof2) + "]"
                               : "null") +
          ", \"bands\": " + std::to_string(test.bands) + ", \"verdict\": " + json_string(test.verdict) + "}\n}\n";
  return text;
}

int compare_command(const Args& args) {
  const std::string usage = kCompareUsage;
  po::options_description opts("options");
  std::string result, measurement, format = "table", sensor, column;
  double measured_position = NAN;
  double fmin = 0.0, fmax = INFINITY, records = 0.0, test_level = 0.05;
  long long skip_rows = -1;
  opts.add_options()("result", po::value(&result)->required(), "result file (HDF5)")(
      "measurement", po::value(&measurement)->required(), "measured PSD (CSV)")(
      "sensor", po::value(&sensor),
      "sensor name, or the number K of sensor_K (1-based; default: sensor_mean if present, else the first)")(
      "measured-position", po::value(&measured_position),
      "where the measurement was taken (m): the sensor nearest it, within half the sensors' smallest spacing")(
      "column", po::value(&column),
      "PSD column of the measurement CSV (default: psd, else the only column besides frequency_hz)")(
      "measured-averages", po::value(&records), "independent records averaged into the measurement (>= 1)")(
      "fmin", po::value(&fmin)->default_value(0.0), "lowest band edge (Hz)")(
      "fmax", po::value(&fmax)->default_value(INFINITY, "inf"), "highest band edge (Hz)")(
      "format", po::value(&format)->default_value("table"), "table, csv or json")(
      "test-level", po::value(&test_level)->default_value(0.05), "level of the combined test (0 < A < 1)")(
      "skip-rows", po::value(&skip_rows), "measurement CSV lines before its header (default: found from the data)");
  po::positional_options_description pos;
  pos.add("result", 1).add("measurement", 1);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;
  if (format != "table" && format != "csv" && format != "json")
    throw usage_error("--format " + format.substr(0, 200) + ": allowed: table, csv or json");
  if (!(fmin >= 0.0) || std::isinf(fmin))
    throw usage_error("--fmin " + number_text(fmin) + ": allowed: a finite frequency >= 0 Hz");
  if (!(fmax > fmin))
    throw usage_error("--fmax " + number_text(fmax) + ": allowed: a frequency above --fmin (" + number_text(fmin) +
                      " Hz)");
  if (!(test_level > 0.0 && test_level < 1.0))
    throw usage_error("--test-level " + number_text(test_level) + ": allowed: a level 0 < A < 1, e.g. 0.05");
  const bool predict = vm.count("measured-averages") > 0;
  if (predict && !(records >= 1.0 && std::isfinite(records)))
    throw usage_error("--measured-averages " + number_text(records) +
                      ": allowed: a finite count >= 1 of independent records");

  const io::SensorChoice choice = io::sensor_choice(
      sensor, vm.count("measured-position") ? std::optional<double>(measured_position) : std::nullopt);
  const io::Hdf5Reader r(result);
  io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
  const io::BandLevels b = io::read_band_levels(r, choice);
  if (vm.count("skip-rows") && skip_rows < 0)
    throw usage_error("--skip-rows " + std::to_string(skip_rows) +
                      ": allowed: a whole number >= 0 (lines before the header)");
  const Measurement m = read_measurement(measurement, column, skip_rows, "compare");
  const bool has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  const int pct = static_cast<int>(std::lround(100.0 * b.confidence));
  const std::string question =
      !has_interval ? "none: " + b.interval_method
      : predict     ? "is the measured level inside the " + std::to_string(pct) +
                      " % prediction interval of a measurement averaged over M = " + number_text(records) +
                      " independent records?"
                : "is the measured level inside the " + std::to_string(pct) +
                      " % interval of the simulated mean? (it ignores the measurement's own scatter; give "
                      "--measured-averages M to ask whether a measurement of M records agrees with the model)";

  const std::vector<BandRow> rows = band_rows(b, m, measurement, fmin, fmax, predict ? records : 0.0);
  if (rows.empty()) throw data_error(measurement + ": covers none of the result's bands inside [fmin, fmax]");
  if (has_interval && predict) warn_band_rules(r, b, rows, records);
  double sq = 0.0;
  int inside = 0;
  for (const auto& row : rows) {
    sq += row.delta * row.delta;
    inside += predict ? row.inside_prediction : row.inside_ci;
  }
  const double rms = std::sqrt(sq / static_cast<double>(rows.size()));
  const int judged = has_interval ? static_cast<int>(rows.size()) : 0;
  const LossOfContact loss = loss_of_contact(r);
  const std::string source = "result " + result + " (" + std::to_string(b.realisations) + " realisations), sensor " +
                             b.sensor + "; measurement " + measurement + ", column " +
                             (column.empty() ? "psd" : column);

  std::vector<std::size_t> band_index;
  std::vector<double> measured_db;
  for (const auto& row : rows) band_index.push_back(row.band), measured_db.push_back(row.measured);
  const CombinedTest test = combined_test(b, band_index, measured_db, predict ? records : 0.0, test_level);

  // Printed only once every band is computed: a refused input leaves no partial output.
  const Comparison c{result,       measurement, column, b,      rows,   predict, records,
                     has_interval, question,    rms,    inside, judged, test,    loss};
  std::string text;
  char buf[320];
  // On stderr too: a result dominated by impacts (or a linearised law past its validity) is no
  // comparison of the roughness model, whatever the form the table is read in.
  if (!b.pick_note.empty()) std::cerr << "rollspec compare: " << b.pick_note << "\n";
  if (!loss.warning.empty()) std::cerr << "rollspec compare: WARNING: " << result << ": " << loss.warning << "\n";
  if (format == "json") {
    std::fputs(json_text(c).c_str(), stdout);
    return 0;
  }
  if (format == "csv")
    text +=
        "centre_hz,simulated_db,measured_db,delta_db,ci_lower_db,ci_upper_db,prediction_lower_db,prediction_upper_db,"
        "inside\n";
  else {
    text += source + "\n" + (loss.warning.empty() ? "" : "WARNING: " + loss.warning + "\n") + "question: " + question +
            "\n";
    std::snprintf(buf, sizeof buf, "%10s %12s %12s %8s %17s %17s %7s\n", "centre_Hz", "simulated_dB", "measured_dB",
                  "delta_dB", "mean_interval_dB", predict ? "prediction_dB" : "", "inside");
    text += buf;
  }
  for (const auto& x : rows) {
    const bool in = predict ? x.inside_prediction : x.inside_ci;
    if (format == "csv") {
      auto cell = [](double v) {
        return std::isfinite(v) ? json_number(v) : std::isnan(v) ? std::string() : v > 0 ? "inf" : "-inf";
      };
      text += number_text(x.centre) + "," + cell(x.simulated) + "," + cell(x.measured) + "," + cell(x.delta) + "," +
              cell(x.ci_lower) + "," + cell(x.ci_upper) + "," + cell(x.pred_lower) + "," + cell(x.pred_upper) + "," +
              (has_interval ? (in ? "1" : "0") : "") + "\n";
    } else {
      char ci[40] = "", pi[40] = "";
      std::snprintf(ci, sizeof ci, "%7.2f..%-7.2f", x.ci_lower, x.ci_upper);
      if (predict && has_interval) std::snprintf(pi, sizeof pi, "%7.2f..%-7.2f", x.pred_lower, x.pred_upper);
      std::snprintf(buf, sizeof buf, "%10g %12.2f %12.2f %8.2f %17s %17s %7s\n", x.centre, x.simulated, x.measured,
                    x.delta, ci, pi, has_interval ? (in ? "yes" : "no") : "-");
      text += buf;
    }
  }
  std::snprintf(buf, sizeof buf, "rms_db_error: %.3f  inside_ci: %d/%d\n", rms, has_interval ? inside : 0, judged);
  // Without M there is no test (it asks whether the measurement is a mean of M records): no line.
  const std::string test_line = predict ? "combined_test: " + test.verdict + "\n" : std::string();
  if (format == "csv")
    text += "# " + source + "\n" + (loss.warning.empty() ? "" : "# WARNING: " + loss.warning + "\n") +
            "# question: " + question + "\n" + (predict ? "# " + test_line : "") + "# " + buf;
  else
    text += test_line + buf;
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace rollspec::cli
