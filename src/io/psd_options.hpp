#pragma once
// The options of `rollspec psd`, with their rules written once: the command checks its flags with these
// functions, and the Python module (rollspec.spectra: welch, bands, read_measurement) its keyword
// arguments of the same names. A refusal is a usage error (exit 64; ValueError in Python) naming the
// option as its caller spells it.
#include <optional>
#include <string>
#include <vector>

#include "kernels/spectral/welch.hpp"
#include "src/io/signal_file.hpp"

namespace rollspec::io {

// How a refusal names an option and its value: the command's "--segment 2: allowed: ...", the module's
// "segment = 2: allowed: ..." (its keyword argument, '_' for '-').
enum class OptionSpelling { command, python };

// --segment, --overlap, --window, and the detrending (always the mean for the command; the module's
// `detrend`).
struct WelchOptions {
  long long segment = 1024;
  double overlap = 0.5;
  std::string window = "hann";  // the spellings of the study key spectrum.window, or rect
  std::string detrend = "mean";
};

// The Welch estimator (D-15) of `o`; its sample_rate is for the caller to set (the file's, or --fs).
spectral::WelchConfig welch_options(const WelchOptions& o, OptionSpelling spelling);

// The options that read a signal file, as given (nullopt or empty: not given).
struct SignalOptions {
  std::optional<double> fs;                // --fs (Hz)
  std::vector<std::string> columns;        // --column, repeatable
  std::string unit;                        // --unit
  std::optional<double> scale;             // --scale
  std::optional<std::string> time_column;  // --time-column
  std::optional<long long> skip_rows;      // --skip-rows
};

// The io::SignalRequest of `o`: --fs, --skip-rows and --time-column checked here (--unit, --scale and
// --column by prepare_signal, which knows the file).
io::SignalRequest signal_request(const SignalOptions& o, OptionSpelling spelling);

}  // namespace rollspec::io
