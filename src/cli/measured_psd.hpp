#pragma once
// A measured PSD as compare and fit read it (frequency_hz and a one-sided PSD column).
#include <string>
#include <vector>

namespace rollspec::cli {

struct Measurement {
  std::vector<double> frequency, psd;
};

// A spreadsheet export of a measured PSD: preamble lines before the header skipped (and said), or
// --skip-rows; delimiter and decimal comma as `rollspec psd` reads a signal. Without --column the PSD
// is `psd`, else, in a `rollspec psd` output (its first line states the PSD unit), the only column
// besides frequency_hz (named after the channel), said on stderr; `column` is set to the one read.
Measurement read_measurement(const std::string& path, std::string& column, long long skip_rows,
                             const std::string& command);

}  // namespace rollspec::cli
