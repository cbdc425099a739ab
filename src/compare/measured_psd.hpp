#pragma once
// A measured PSD as compare and fit read it (frequency_hz and a one-sided PSD column), through
// io::read_psd_csv (src/io/psd_csv.hpp), with its notes said on stderr.
#include <optional>
#include <string>
#include <vector>

#include "src/io/psd_csv.hpp"

namespace rollspec::compare {

struct Measurement {
  std::vector<double> frequency, psd;
  std::optional<io::PsdCsvMetadata> metadata;  // rollspec psd's sidecar, when it records this CSV's SHA-256
};

// A spreadsheet export of a measured PSD: preamble lines before the header skipped (and said), or
// --skip-rows; delimiter and decimal comma as `rollspec psd` reads a signal. Without --column the PSD
// is `psd`, else, in a `rollspec psd` output, the only PSD column (said on stderr); several and no
// --column: refused naming --column and the columns. `column` is set to the title read.
Measurement read_measurement(const std::string& path, std::string& column, long long skip_rows,
                             const std::string& command);

// The band compare and fit test, --fmin and --fmax, checked before any file is read (exit 64).
void check_frequency_range(double fmin, double fmax);

}  // namespace rollspec::compare
