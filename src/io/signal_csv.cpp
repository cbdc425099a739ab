// A measured signal in CSV/text: every column a channel, except a time column, which gives the rate.
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/time_column.hpp"

namespace rollspec::io {

SignalTable read_csv_signal(const std::string& path) {
  CsvTable t = read_csv(path);
  SignalTable s;
  s.file = path;
  s.format = std::string("CSV text (") + delimiter_name(t.delimiter) + "-delimited" + (t.decimal_comma ? ", decimal comma)" : ")");
  s.unit = "as stored";
  std::size_t time = t.columns.size();
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (time_column_unit(t.columns[c]) == 0.0) continue;
    if (time < t.columns.size())
      throw data_error(path + ":1: two time columns, '" + clip(t.columns[time]) + "' and '" + clip(t.columns[c]) +
                       "'; allowed: at most one column named like a time (t, time, time_s, Time (s), t [ms], ...)");
    time = c;
  }
  if (time < t.columns.size()) {
    s.time_column = t.columns[time];
    s.time_samples = t.rows();
    s.sample_rate = rate_from_time_stamps(t.values[time], time_column_unit(s.time_column), s.time_column,
                                          [&](std::size_t row) { return t.where(row); });
    s.rate_source = "time column '" + s.time_column + "'";
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
