// A measured signal in CSV/text: every column a channel, except a time column, which gives the rate.
// Logger exports are read as they come (preamble lines, decimal commas, rounded stamps), and every
// choice made for the user is put in SignalTable::notes.
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/number_text.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/time_column.hpp"

namespace rollspec::io {

namespace {
std::string format_of(const CsvTable& t) {
  if (t.delimiter == 0) return "CSV text (one column, decimal comma)";
  return std::string("CSV text (") + delimiter_name(t.delimiter) + "-delimited" +
         (t.decimal_comma ? ", decimal comma)" : ")");
}

std::string column_list(const CsvTable& t) {
  std::string s;
  for (const auto& c : t.columns) s += (s.empty() ? "" : ", ") + c;
  return clip(s, 400);
}

// The time column: --time-column's, none, or the one column named like a time.
std::size_t find_time_column(const CsvTable& t, const std::string& path, const std::string& asked) {
  const std::size_t none = t.columns.size();
  if (asked == "none") return none;
  if (!asked.empty()) {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      if (t.columns[c] == asked) return c;
    throw usage_error("--time-column " + clip(asked) + ": no such column in " + path +
                      "; columns found: " + column_list(t) + "; allowed: one of them, or none");
  }
  std::size_t time = none;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (time_column_unit(t.columns[c]) == 0.0) continue;
    if (time < none)
      throw data_error(path + ":" + std::to_string(t.header_line) + ": two time columns, '" + clip(t.columns[time]) +
                       "' and '" + clip(t.columns[c]) +
                       "'; allowed: at most one column named like a time (t, time, time_s, Time (s), t [ms], ...), " +
                       "or --time-column NAME to pick one (the other is then a channel)");
    time = c;
  }
  return time;
}

void layout_notes(SignalTable& s, const CsvTable& t) {
  const std::string f = s.file + ": ";
  if (t.delimiter == 0)
    s.notes.push_back(f +
                      "one column with a decimal comma (every row holds one ',' and the header none), not two "
                      "comma-delimited columns");
  else
    s.notes.push_back(f + delimiter_name(t.delimiter) + "-delimited (from the " +
                      (t.layout_found ? "data rows" : "header line") + ")" +
                      (t.decimal_comma ? ", decimal comma" : ""));
  if (t.preamble_lines > 0)
    s.notes.push_back(f + "skipped " + counted(static_cast<unsigned long long>(t.preamble_lines), "preamble line") +
                      " before the header '" + clip(t.header_text) + "' (line " + std::to_string(t.header_line) +
                      "; --skip-rows N says where it is)");
}

// The rate from the time column, or --fs over it (said, with what the stamps say).
void rate_from_column(SignalTable& s, const CsvTable& t, std::size_t time, const SignalRequest& r) {
  const double unit = time_column_unit(t.columns[time]);
  const double seconds =
      unit == 0.0 ? 1.0 : unit;  // a column picked by --time-column with no unit in its name: seconds
  const PrintedDigits digits{t.decimals[time], t.significant[time]};
  const auto where = [&](std::size_t row) { return t.where(row); };
  const std::string f = s.file + ": ";
  if (r.fs > 0.0) {
    std::string stamps;
    try {
      stamps = "its stamps imply " +
               rate_text(rate_from_time_stamps(t.values[time], seconds, s.time_column, where, digits)) + " Hz";
    } catch (const UserError& e) {
      stamps = "its stamps are refused: " + std::string(e.what());
    }
    s.notes.push_back(f + "--fs " + rate_text(r.fs) + " Hz overrides the time column '" + s.time_column + "' (" +
                      clip(stamps, 300) + ")");
    return;  // sample_rate 0: prepare_signal takes --fs
  }
  try {
    s.sample_rate = rate_from_time_stamps(t.values[time], seconds, s.time_column, where, digits);
  } catch (const UserError& e) {
    if (!r.time_column.empty()) throw;
    // taken by its name: it may be no time at all (a counter named t)
    throw UserError(e.exit_code(), std::string(e.what()) + "; or, if '" + clip(s.time_column) +
                                       "' holds no time stamps: --time-column none (with --fs), or --time-column NAME");
  }
  s.rate_source = "time column '" + s.time_column + "'";
  s.notes.push_back(f + "sample rate " + rate_text(s.sample_rate) + " Hz from the time column '" + s.time_column + "'" +
                    (unit == 0.0   ? " (--time-column; its name gives no unit: seconds)"
                     : unit == 1.0 ? " (seconds)"
                                   : " (milliseconds)") +
                    "; --fs HZ overrides it");
}
}  // namespace

SignalTable read_csv_signal(const std::string& path, const SignalRequest& r) {
  CsvReadOptions options;
  options.find_header = true;
  options.skip_rows = r.skip_rows;
  CsvTable t = read_csv(path, options);
  SignalTable s;
  s.file = path;
  s.format = format_of(t);
  s.unit = "as stored";
  layout_notes(s, t);
  const std::size_t time = find_time_column(t, path, r.time_column);
  if (time < t.columns.size()) {
    s.time_column = t.columns[time];
    s.time_samples = t.rows();
    rate_from_column(s, t, time, r);
  }
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (c == time) continue;
    s.channels.push_back(t.columns[c]);
    s.groups.push_back(t.columns[c]);
    s.values.push_back(std::move(t.values[c]));
  }
  return s;
}

}  // namespace rollspec::io
