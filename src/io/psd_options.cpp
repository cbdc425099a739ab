// `rollspec psd`'s option rules (psd_options.hpp), for the command and the Python module.
#include "src/io/psd_options.hpp"

#include <cmath>

#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/study/sections/spectrum_section.hpp"

namespace rollspec::io {

namespace {

// "--name value: allowed: what" (the command; its numbers as std::to_string prints them) or
// "name = value: allowed: what" (the module; numbers as number_text, texts quoted).
[[noreturn]] void refuse(OptionSpelling spelling, std::string name, const std::string& command_value,
                         const std::string& python_value, const std::string& allowed) {
  if (spelling == OptionSpelling::command)
    throw usage_error("--" + name + " " + command_value + ": allowed: " + allowed);
  for (char& c : name)
    if (c == '-') c = '_';
  throw usage_error(name + " = " + python_value + ": allowed: " + allowed);
}

[[noreturn]] void refuse(OptionSpelling spelling, const std::string& name, double value, const std::string& allowed) {
  refuse(spelling, name, std::to_string(value), io::number_text(value), allowed);
}

[[noreturn]] void refuse(OptionSpelling spelling, const std::string& name, long long value,
                         const std::string& allowed) {
  refuse(spelling, name, std::to_string(value), std::to_string(value), allowed);
}

[[noreturn]] void refuse(OptionSpelling spelling, const std::string& name, const std::string& value,
                         const std::string& allowed) {
  refuse(spelling, name, value.empty() ? "''" : clip(value), "'" + clip(value) + "'", allowed);
}

// The spellings of the study key spectrum.window (one table), and `rect`, the short form psd took before
// and its CSV metadata still writes.
spectral::Window window_choice(const std::string& text, OptionSpelling spelling) {
  if (text == "rect") return spectral::Window::rectangular;
  std::string allowed;
  for (const auto& c : study::kWelchWindows) {
    if (text == c.spelling) return c.value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(c.spelling);
  }
  refuse(spelling, "window", text, allowed + " (or rect)");
}

// The module's `detrend`: the segment's mean removed (the command's, also spelt constant, scipy's word),
// or nothing.
constexpr study::ChoiceTable<spectral::Detrend, 3> kDetrends{{
    {spectral::Detrend::constant, "mean", ""},
    {spectral::Detrend::constant, "constant", ""},
    {spectral::Detrend::none, "none", ""},
}};

spectral::Detrend detrend_choice(const std::string& text, OptionSpelling spelling) {
  for (const auto& c : kDetrends)
    if (text == c.spelling) return c.value;
  refuse(spelling, "detrend", text, "mean (also constant), none");
}

}  // namespace

spectral::WelchConfig welch_options(const WelchOptions& o, OptionSpelling spelling) {
  if (o.segment < 4) refuse(spelling, "segment", o.segment, "a whole number >= 4");
  if (!(o.overlap >= 0.0 && o.overlap <= 0.95)) refuse(spelling, "overlap", o.overlap, "a fraction in [0, 0.95]");
  spectral::WelchConfig c;
  c.segment = static_cast<std::size_t>(o.segment);
  c.overlap = static_cast<std::size_t>(std::floor(o.overlap * static_cast<double>(o.segment)));
  c.window = window_choice(o.window, spelling);
  c.detrend = detrend_choice(o.detrend, spelling);
  return c;
}

io::SignalRequest signal_request(const SignalOptions& o, OptionSpelling spelling) {
  io::SignalRequest r;
  if (o.fs) {
    if (!(*o.fs > 0.0) || !std::isfinite(*o.fs)) refuse(spelling, "fs", *o.fs, "a finite number > 0 (Hz)");
    r.fs = *o.fs;
  }
  if (o.skip_rows) {
    if (*o.skip_rows < 0) refuse(spelling, "skip-rows", *o.skip_rows, "a whole number >= 0 (lines before the header)");
    r.skip_rows = *o.skip_rows;
  }
  if (o.time_column) {
    if (o.time_column->empty()) refuse(spelling, "time-column", *o.time_column, "a column name, or none");
    r.time_column = *o.time_column;
  }
  r.columns = o.columns;
  r.unit = o.unit;
  r.scale_given = o.scale.has_value();
  if (o.scale) r.scale = *o.scale;
  return r;
}

}  // namespace rollspec::io
