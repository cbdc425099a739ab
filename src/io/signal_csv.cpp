// A measured signal in CSV/text: every column a channel, except a time column, which gives the rate.
// Logger exports are read as they come (preamble lines, units rows, decimal commas, rounded stamps,
// UTF-16), units are read from the names and the units row, and every choice made for the user is put
// in SignalTable::notes.
#include <cmath>
#include <optional>

#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/measurement_unit.hpp"
#include "src/io/number_text.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/time_column.hpp"

namespace rollspec::io {

namespace {
std::string format_of(const CsvTable& t) {
  std::string f = t.delimiter == 0 ? "CSV text (one column, decimal comma"
                                   : std::string("CSV text (") + delimiter_name(t.delimiter) + "-delimited" +
                                         (t.decimal_comma ? ", decimal comma" : "");
  if (!t.encoding.empty()) f += ", " + t.encoding;
  return f + ")";
}

std::string column_list(const CsvTable& t) {
  std::string s;
  for (const auto& c : t.columns) s += (s.empty() ? "" : ", ") + c;
  return clip(s, 400);
}

// What the header and the units row say of one column.
struct ColumnUnit {
  std::string conflict;  // the refusal when name and units row disagree
  NamedUnit named;
  std::string row;  // the units row's cell ("" if none)
  std::optional<MeasurementUnit> row_unit;
  double seconds = 0.0;  // > 0: a time column (auto), seconds per unit
};

ColumnUnit column_unit(const CsvTable& t, std::size_t c) {
  ColumnUnit u;
  u.named = unit_in_name(t.columns[c]);
  if (!t.units.empty()) {
    u.row = t.units[c];
    u.row_unit = parse_measurement_unit(u.row);
  }
  if (u.named.unit && u.row_unit && u.named.unit->text != u.row_unit->text)
    u.conflict = t.file + ":" + std::to_string(t.units_line) + ": column '" + clip(t.columns[c]) + "' is in " +
                 u.named.unit->text + " by its name but in " + u.row_unit->text +
                 " by the units row; allowed: one unit per column (--unit UNIT says a channel's, --fs HZ "
                 "overrides a time column)";
  const auto is_time = [](const std::optional<MeasurementUnit>& m) { return m && m->quantity == Quantity::time; };
  const bool named_time = time_like_name(u.named, t.columns[c]);
  if (named_time && !u.named.unit && !u.row_unit && u.named.written.empty())
    u.seconds = 1.0;
  else if ((named_time || u.named.bracketed) && is_time(u.named.unit))
    u.seconds = u.named.unit->factor;
  else if (!u.named.unit && is_time(u.row_unit))
    u.seconds = u.row_unit->factor;
  return u;
}

// The time columns: --time-column's, none, or those named like a time or with a time unit.
std::vector<std::size_t> time_columns(const CsvTable& t, const std::vector<ColumnUnit>& units,
                                      const std::string& asked) {
  if (asked == "none") return {};
  if (!asked.empty()) {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      if (t.columns[c] == asked) return {c};
    throw usage_error("--time-column " + clip(asked) + ": no such column in " + t.file +
                      "; columns found: " + column_list(t) + "; allowed: one of them, or none");
  }
  std::vector<std::size_t> found;
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (units[c].seconds > 0.0) found.push_back(c);
  return found;
}

void layout_notes(SignalTable& s, const CsvTable& t) {
  const std::string f = s.file + ": ";
  if (!t.encoding.empty()) s.notes.push_back(f + t.encoding + " text (byte-order mark), read as UTF-8");
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
                      (t.preamble_rows > 0 ? " (" + counted(t.preamble_rows, "row") +
                                                 " of numbers among them: the data are the longer table after them)"
                                           : std::string()) +
                      " before the header '" + clip(t.header_text) + "' (line " + std::to_string(t.header_line) +
                      "; --skip-rows N says where it is)");
  if (t.units_line > 0) s.notes.push_back(f + "line " + std::to_string(t.units_line) + " is a units row");
}

std::string stamps_refused_hint(const std::string& name) {
  return "; if the samples are evenly spaced and only the stamps are off: --fs HZ, which overrides the time "
         "column; if '" +
         clip(name) + "' holds no time stamps: --time-column none (with --fs), or --time-column NAME";
}

// The rate from a time column, or --fs over it (said, with what the stamps say).
void rate_from_column(SignalTable& s, const CsvTable& t, std::size_t time, double seconds, const std::string& unit_note,
                      const SignalRequest& r) {
  const PrintedDigits digits{t.decimals[time], t.significant[time]};
  const auto where = [&](std::size_t row) { return t.where(row); };
  const std::string f = s.file + ": ";
  const std::string& name = t.columns[time];
  if (r.fs > 0.0) {
    std::string stamps;
    try {
      stamps =
          "its stamps imply " + rate_text(rate_from_time_stamps(t.values[time], seconds, name, where, digits)) + " Hz";
    } catch (const UserError& e) {
      stamps = "its stamps are refused: " + std::string(e.what());
    }
    s.notes.push_back(f + "--fs " + rate_text(r.fs) + " Hz overrides the time column '" + name + "' (" +
                      clip(stamps, 300) + ")");
    return;  // sample_rate 0: prepare_signal takes --fs
  }
  try {
    s.sample_rate = rate_from_time_stamps(t.values[time], seconds, name, where, digits);
  } catch (const UserError& e) {
    const std::string what = e.what();
    if (!r.time_column.empty() || what.find("--fs HZ") != std::string::npos) throw;
    throw UserError(e.exit_code(), what + stamps_refused_hint(name));
  }
  s.rate_source = "time column '" + name + "'";
  s.notes.push_back(f + "sample rate " + rate_text(s.sample_rate) + " Hz from the time column '" + name + "' (" +
                    unit_note + "); --fs HZ overrides it");
}

// Several columns named like a time: read if their stamps agree on the rate (the first gives it, the
// others are no channels), else refused naming --time-column.
void check_other_time_columns(SignalTable& s, const CsvTable& t, const std::vector<ColumnUnit>& units,
                              const std::vector<std::size_t>& times) {
  std::string rates;
  bool agree = true;
  for (const auto c : times) {
    std::string rate;
    try {
      const double hz = rate_from_time_stamps(
          t.values[c], units[c].seconds, t.columns[c], [&](std::size_t row) { return t.where(row); },
          PrintedDigits{t.decimals[c], t.significant[c]});
      rate = rate_text(hz) + " Hz";
      if (s.sample_rate > 0.0 && std::fabs(hz - s.sample_rate) > kRateTolerance * s.sample_rate) agree = false;
    } catch (const UserError& e) {
      rate = "refused: " + clip(e.what(), 200);
      agree = false;
    }
    rates += (rates.empty() ? "" : ", ") + ("'" + clip(t.columns[c]) + "' " + rate);
    if (c != times.front()) s.skipped.emplace_back(t.columns[c], "a second time column");
  }
  if (!agree)
    throw data_error(t.file + ":" + std::to_string(t.header_line) + ": " + counted(times.size(), "time column") +
                     " that disagree (" + rates + "); allowed: --time-column NAME to pick one (the others are then " +
                     "channels: pick the channels with --column), or --fs HZ");
  s.notes.push_back(s.file + ": " + counted(times.size(), "time column") + " (" + rates + "): the rate from '" +
                    t.columns[times.front()] + "', the others are no channels (--time-column NAME picks one)");
}

ChannelUnit channel_unit(const CsvTable& t, const ColumnUnit& u) {
  ChannelUnit ch;
  ch.conflict = u.conflict;
  // A time unit after '_' (`acc_s`) may be part of a name; a time unit in brackets or a units row is one.
  const bool named = u.named.unit && (u.named.bracketed || u.named.unit->quantity != Quantity::time);
  const auto& unit = named ? u.named.unit : u.row_unit;
  if (!unit) return ch;
  ch.text = unit->text;
  ch.written = named ? u.named.written : u.row;
  ch.factor = unit->quantity == Quantity::acceleration ? unit->factor : 0.0;
  ch.origin = named ? UnitOrigin::name : UnitOrigin::units_row;
  ch.where = named ? "its name" : "the units row (line " + std::to_string(t.units_line) + ")";
  return ch;
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
  std::vector<ColumnUnit> units;
  for (std::size_t c = 0; c < t.columns.size(); ++c) units.push_back(column_unit(t, c));
  const auto times = time_columns(t, units, r.time_column);
  const std::size_t time = times.empty() ? t.columns.size() : times.front();
  if (!times.empty()) {
    if (!units[time].conflict.empty() && r.fs <= 0.0) throw data_error(units[time].conflict);
    s.time_column = t.columns[time];
    s.time_samples = t.rows();
    double seconds = units[time].seconds;
    const bool by_row = !units[time].named.unit && units[time].row_unit;
    std::string unit_note = time_unit_words(seconds) + (by_row ? ", by the units row" : "");
    if (!r.time_column.empty()) {  // picked by --time-column: its own unit if it has one
      seconds = time_unit_in_name(s.time_column);
      unit_note = time_unit_words(seconds) + " by its name, --time-column";
      if (seconds == 0.0 && units[time].row_unit && units[time].row_unit->quantity == Quantity::time) {
        seconds = units[time].row_unit->factor;
        unit_note = time_unit_words(seconds) + " by the units row, --time-column";
      }
      if (seconds == 0.0) {
        seconds = 1.0;
        unit_note = "--time-column; its name gives no unit: seconds";
      }
    }
    rate_from_column(s, t, time, seconds, unit_note, r);
    if (times.size() > 1 && r.fs <= 0.0) check_other_time_columns(s, t, units, times);
  }
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (c == time) continue;
    bool other_time = false;
    for (const auto k : times) other_time = other_time || k == c;
    if (other_time) {
      if (r.fs > 0.0) s.skipped.emplace_back(t.columns[c], "a second time column");
      continue;
    }
    s.channels.push_back(t.columns[c]);
    s.groups.push_back(t.columns[c]);
    s.values.push_back(std::move(t.values[c]));
    s.units.push_back(channel_unit(t, units[c]));
  }
  return s;
}

}  // namespace rollspec::io
