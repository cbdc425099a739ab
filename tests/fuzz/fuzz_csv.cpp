// libFuzzer harness over the numeric CSV reader (rollspec::io::read_csv) that reads measured
// signals (`rollspec psd`), measured PSDs (`rollspec compare`), PSD tables and profiles.
//
// The input is written to a temporary file and read; a table that is accepted is then checked
// the way the commands check theirs (named columns, strictly increasing axis). It is also read as a
// measured signal (delimiter and decimal-comma detection, time column and its sample rate). A
// UserError is the expected refusal; any other exception, a crash or a sanitizer report is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/signal_file.hpp"
#include "fuzz_temp_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollspec::fuzz::TempFile file("csv", ".csv");
  file.write(reinterpret_cast<const char*>(data), size);
  try {
    const rollspec::io::CsvTable t = rollspec::io::read_csv(file.path);
    // Invariants of an accepted table: a header, at least one row, every column as long as the
    // row list, every value finite.
    if (t.columns.empty() || t.rows() == 0 || t.values.size() != t.columns.size()) std::abort();
    for (const auto& col : t.values) {
      if (col.size() != t.rows()) std::abort();
      for (double v : col)
        if (!std::isfinite(v)) std::abort();
    }
    for (std::size_t r = 0; r < t.rows(); ++r) (void)t.where(r);
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      if (t.column_index(t.columns[c]) != c) std::abort();  // column names are unique
      try {
        rollspec::io::require_increasing(t, c);
      } catch (const rollspec::UserError&) {
      }
    }
    (void)t.column("frequency_hz");
  } catch (const rollspec::UserError&) {
    // Refused with a message naming the file (and line/column): the expected outcome.
  }
  try {
    // As a signal: channels are the columns minus at most one time column, all of one length; a time
    // column gives a finite rate > 0, and there is no rate without one.
    const rollspec::io::SignalTable s = rollspec::io::read_csv_signal(file.path);
    if (s.channels.size() != s.values.size() || s.groups.size() != s.channels.size()) std::abort();
    if (s.units.size() != s.channels.size()) std::abort();  // one unit (or none found) per channel
    for (const auto& col : s.values)
      if (col.size() != s.values.front().size()) std::abort();
    if (s.time_column.empty() != (s.sample_rate == 0.0)) std::abort();
    if (!s.time_column.empty() && !(std::isfinite(s.sample_rate) && s.sample_rate > 0.0)) std::abort();
  } catch (const rollspec::UserError&) {
  }
  return 0;
}
