#include "src/compare/comparison.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "kernels/spectral/ensemble_interval.hpp"
#include "src/compare/measured_psd.hpp"
#include "src/compare/verdict_references.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/psd_csv.hpp"
#include "src/io/references.hpp"
#include "src/io/sweep_point.hpp"

namespace rollspec::compare {

namespace {

using io::number_text;

// Every option's value checked before any file is read (--format is the command's own).
void check_request(const CompareRequest& q) {
  check_frequency_range(q.fmin, q.fmax);
  if (!(q.test_level > 0.0 && q.test_level < 1.0))
    throw usage_error("--test-level " + number_text(q.test_level) + ": allowed: a level 0 < A < 1, e.g. 0.05");
  if (!(q.noise_margin_db >= 0.0 && std::isfinite(q.noise_margin_db)))
    throw usage_error("--noise-margin " + number_text(q.noise_margin_db) + ": allowed: a finite margin >= 0 dB");
  if (q.measured_averages && !(*q.measured_averages >= 1.0 && std::isfinite(*q.measured_averages)))
    throw usage_error("--measured-averages " + number_text(*q.measured_averages) +
                      ": allowed: a finite count >= 1 of independent rolls");
  if (q.skip_rows && *q.skip_rows < 0)
    throw usage_error("--skip-rows " + std::to_string(*q.skip_rows) +
                      ": allowed: a whole number >= 0 (lines before the header)");
  if (q.fs && !(*q.fs > 0.0 && std::isfinite(*q.fs)))
    throw usage_error("--fs " + number_text(*q.fs) + ": allowed: a finite sample rate > 0 Hz");
}

io::SignalRequest signal_request(const CompareRequest& q) {
  io::SignalRequest s;
  s.columns = q.columns;
  s.unit = q.unit;
  if (q.scale) s.scale = *q.scale;
  s.scale_given = q.scale.has_value();
  if (q.fs) s.fs = *q.fs;
  s.time_column = q.time_column;
  if (q.skip_rows) s.skip_rows = *q.skip_rows;
  return s;
}

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

// A PSD table as the measurement: on the model's grid when its points are the model's bins. `column` is
// set to the title read; the choices made reading it go to `say`.
MeasuredSpectrum psd_table(const std::string& path, std::string& column, long long skip_rows, double df,
                           const std::function<void(const std::string&)>& say) {
  io::PsdCsv t = io::read_psd_csv(path, column, skip_rows);
  for (const auto& note : t.notes) say(note);
  column = t.column;
  MeasuredSpectrum m;
  m.source = path;
  m.frequency = std::move(t.frequency);
  m.psd = std::move(t.psd);
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

// The result's references, then the verdict's own, each once (lines "id | citation | doi").
std::vector<CitedReference> cited_references(const io::Hdf5Reader& r, const std::vector<std::string>& verdict_ids) {
  std::vector<std::string> lines = io::read_reference_lines(r);
  for (const auto& line : io::reference_lines(verdict_ids))
    if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  std::vector<CitedReference> out;
  for (const auto& line : lines) {
    const std::size_t a = line.find(" | "), b = line.rfind(" | ");
    if (a == std::string::npos || b == a) continue;  // not a reference line: nothing to quote
    out.push_back({line.substr(0, a), line.substr(a + 3, b - a - 3), line.substr(b + 3)});
  }
  return out;
}

}  // namespace

Comparison compare_result(const CompareRequest& q) {
  check_request(q);
  const io::SignalRequest signal = signal_request(q);
  VerdictOptions o;
  o.fmin = q.fmin, o.fmax = q.fmax, o.test_level = q.test_level, o.noise_margin_db = q.noise_margin_db;
  o.same_surface = q.same_surface;
  o.floor_check = !q.keep_floor_bands;

  if (q.measurements.empty())
    throw usage_error("no measurement; allowed: the recordings (one file per roll) or one PSD table");
  for (const auto& path : q.measurements) {
    io::require_regular_input(path, "a measurement");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      throw missing_input("cannot read '" + path +
                          "': it is a directory; expected a recording (CSV/text, WAV/FLAC, .mat) or a PSD table (CSV)");
  }
  const io::SensorChoice choice = io::sensor_choice(q.sensor, q.measured_position);
  const io::Hdf5Reader r(q.result);
  io::check_filetype(r, io::kResultFileType, io::kResultSchemaMajor);
  Comparison c;
  c.result = q.result;
  std::function<void(const std::string&)> say = q.reading_note;
  if (!say) say = [&c](const std::string& note) { c.messages.push_back(note); };
  c.bands = io::read_band_levels(r, choice, q.point);
  const io::BandLevels& b = c.bands;
  const io::SweepPoint at = io::sweep_point(r, q.point);
  o.model_psd = mean_psd_row(r, at, b.sensor, o.model_df);

  // The measurement: one PSD table, or recordings through the model's estimator.
  c.psd_table = q.measurements.size() == 1 && is_psd_table(q.measurements[0]);
  c.column = signal.columns.size() == 1 ? signal.columns[0] : "";
  MeasuredSpectrum& m = c.measurement;
  const auto estimator = read_model_estimator(r);
  RecordingOptions ro;
  ro.signal = signal;
  ro.roll_per_channel = q.roll_per_channel;
  ro.model_sensors = sensors_in_row(r, b.sensor);
  if (c.psd_table) {
    if (signal.columns.size() > 1)
      throw usage_error("--column: " + std::to_string(signal.columns.size()) +
                        " columns for a PSD table; allowed: one PSD column");
    m = psd_table(q.measurements[0], c.column, signal.skip_rows, o.model_df, say);
  } else {
    if (!estimator)
      throw data_error(q.result +
                       ": has no record of its estimator (/psd@sample_rate, welch_segment, ...: written "
                       "by this rollspec); re-run the study, or give compare a PSD table of the recording");
    m = measure_recordings(q.measurements, ro, *estimator);
  }
  if (q.measured_averages) {
    const double records = *q.measured_averages;
    if (m.records > 0.0 && records != m.records)
      m.notes.push_back("--measured-averages " + number_text(records) + " replaces M = " + number_text(m.records) +
                        " (" + m.records_source + ")");
    m.records = records;
    m.records_source = "--measured-averages";
  }
  if (!q.noise.empty()) {
    if (is_psd_table(q.noise)) {
      std::string noise_column;
      c.noise = psd_table(q.noise, noise_column, -1, o.model_df, say);
    } else {
      if (!estimator) throw data_error(q.result + ": has no record of its estimator; give --noise as a PSD table");
      c.noise = measure_recordings({q.noise}, ro, *estimator);
    }
    o.noise = &*c.noise;
  }
  c.verdict = band_verdict(b, m, o);
  c.loss = loss_of_contact(r, at);
  c.has_interval = b.realisations >= spectral::kMinRealisationsForInterval;
  c.predict = m.records > 0.0 && c.has_interval;
  c.references = cited_references(r, verdict_references(c.verdict, !c.psd_table, c.predict));

  if (!b.pick_note.empty()) c.messages.push_back(b.pick_note);
  c.messages.insert(c.messages.end(), m.notes.begin(), m.notes.end());
  if (!c.loss.warning.empty()) c.messages.push_back("WARNING: " + q.result + ": " + c.loss.warning);
  if (b.table_error_missing && !q.same_surface && m.records > 0.0)
    c.messages.push_back("WARNING: " + q.result + ": its intervals are conditional on its " + b.table +
                         " (the table's own error was not estimated: [stiffness] table_error = none), so this verdict "
                         "leaves that error out and holds only for the surface the table was built on");
  for (const auto& w : c.verdict.warnings) c.messages.push_back("WARNING: " + w);
  return c;
}

}  // namespace rollspec::compare
