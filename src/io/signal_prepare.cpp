// From a signal file to what Welch needs: the picked channels (--column), one length, the sample rate
// (the file's, checked against --fs), values in m/s² (--unit, --scale).
#include <cmath>
#include <unordered_set>

#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/io/signal_file.hpp"
#include "src/io/time_column.hpp"
#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {
std::string list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return clip(s.empty() ? "(none)" : s, 400);
}

std::string skipped_list(const SignalTable& s) {
  std::string out;
  for (const auto& [name, why] : s.skipped) out += (out.empty() ? "" : ", ") + name + " (" + why + ")";
  return clip(out, 400);
}

bool known(const SignalTable& s, const std::string& name) {
  for (std::size_t i = 0; i < s.channels.size(); ++i)
    if (s.channels[i] == name || s.groups[i] == name) return true;
  for (const auto& k : s.skipped)
    if (k.first == name) return true;
  return name == s.time_column;
}

// --column values: a name as a whole if the file knows it (names may hold commas), else comma-separated names.
std::vector<std::string> requested_names(const SignalTable& s, const std::vector<std::string>& columns) {
  std::vector<std::string> out;
  for (const auto& c : columns) {
    if (known(s, c)) {
      out.push_back(c);
      continue;
    }
    std::size_t from = 0;
    for (;;) {
      const auto comma = c.find(',', from);
      const std::string name = trim(c.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      if (name.empty())
        throw usage_error("--column '" + clip(c) + "': an empty name; allowed: channel names, comma-separated");
      out.push_back(name);
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
  }
  return out;
}

// Indices of the channels picked by `columns` (all if empty), in the order asked.
std::vector<std::size_t> pick(const SignalTable& s, const std::vector<std::string>& columns) {
  std::vector<std::size_t> picked;
  if (columns.empty()) {
    for (std::size_t i = 0; i < s.channels.size(); ++i) picked.push_back(i);
    return picked;
  }
  std::unordered_set<std::size_t> taken;
  for (const auto& name : requested_names(s, columns)) {
    if (name == s.time_column)
      throw usage_error("--column " + clip(name) + ": that is the time column of " + s.file +
                        " (it gives the sample rate and is never a channel); channels: " + list(s.channels));
    std::vector<std::size_t> match;
    for (std::size_t i = 0; i < s.channels.size(); ++i)
      if (s.channels[i] == name) match.push_back(i);
    if (match.empty())  // a matrix variable: all its columns
      for (std::size_t i = 0; i < s.channels.size(); ++i)
        if (s.groups[i] == name) match.push_back(i);
    if (match.empty()) {
      for (const auto& [skip, why] : s.skipped)
        if (skip == name)
          throw data_error(s.file + ": --column " + clip(name) + ": variable '" + skip + "' is " + why +
                           "; allowed: a real numeric vector, or a matrix with one channel per column");
      throw usage_error("--column " + clip(name) + ": no such channel in " + s.file + "; channels found: " +
                        list(s.channels) + (s.skipped.empty() ? "" : "; not channels: " + skipped_list(s)));
    }
    for (const auto i : match) {
      if (!taken.insert(i).second)
        throw usage_error("--column " + clip(name) + ": channel '" + s.channels[i] +
                          "' is picked twice; allowed: each channel once");
      picked.push_back(i);
    }
  }
  return picked;
}
}  // namespace

SignalTable prepare_signal(const std::string& path, const SignalRequest& r) {
  if (!r.unit.empty()) option_units(r.unit);  // a bad --unit is refused before the file is read
  if (!(r.scale > 0.0) || !std::isfinite(r.scale))
    throw usage_error("--scale " + number_text(r.scale) +
                      ": allowed: a finite number > 0 (physical units per file unit or per full scale)");
  SignalTable s = read_signal(path, r);
  // Integer PCM holds fractions of full scale, which is no physical unit: read as 1 g, a 50 g
  // recorder's data would come out 34 dB low without a word.
  if (s.unit == "full scale" && !r.scale_given)
    throw usage_error(path + ": integer PCM (" + s.format +
                      ") holds fractions of the recorder's full scale, not accelerations; " +
                      "give --scale X, the value of full scale in --unit (a recorder whose full scale is 50 g: --scale "
                      "50 --unit g); " +
                      "float sound files are read as stored and need no --scale");
  if (s.channels.empty())
    throw data_error(
        path + ": no channels in this " + s.format +
        (s.time_column.empty() ? "" : "; '" + s.time_column + "' is its time column") +
        (s.skipped.empty() ? "" : "; not channels: " + skipped_list(s)) +
        "; allowed: at least one numeric column (CSV), channel (sound file) or real numeric vector/matrix (.mat)");
  const auto picked = pick(s, r.columns);

  SignalTable out;
  out.file = s.file;
  out.format = s.format;
  out.notes = s.notes;
  out.time_column = s.time_column;
  out.time_samples = s.time_samples;
  for (const auto i : picked) {
    out.channels.push_back(s.channels[i]);
    out.groups.push_back(s.groups[i]);
    out.values.push_back(std::move(s.values[i]));
  }
  for (std::size_t c = 1; c < out.channels.size(); ++c)
    if (out.values[c].size() != out.values[0].size())
      throw data_error(path + ": channel '" + out.channels[0] + "' has " + std::to_string(out.values[0].size()) +
                       " samples but '" + out.channels[c] + "' " + std::to_string(out.values[c].size()) +
                       "; allowed: channels of one length (pick them with --column)");
  if (out.time_samples != 0 && out.time_samples != out.samples())
    throw data_error(path + ": time variable '" + out.time_column + "' has " + std::to_string(out.time_samples) +
                     " stamps but channel '" + out.channels[0] + "' " + std::to_string(out.samples()) +
                     " samples; allowed: one stamp per sample");

  if (r.fs > 0.0) {
    if (s.sample_rate > 0.0 && std::fabs(r.fs - s.sample_rate) > kRateTolerance * s.sample_rate)
      throw usage_error("--fs " + rate_text(r.fs) + " Hz disagrees with " + path + ": " + rate_text(s.sample_rate) +
                        " Hz from " + s.rate_source + "; allowed: an --fs within " + number_text(100 * kRateTolerance) +
                        " % of it, or no --fs (the file's rate is used)");
    out.sample_rate = r.fs;
    out.rate_source = "--fs";
  } else if (s.sample_rate > 0.0) {
    out.sample_rate = s.sample_rate;
    out.rate_source = s.rate_source;
    if (s.time_column.empty() || s.rate_source.rfind("time column", 0) != 0)
      out.notes.push_back(path + ": sample rate " + rate_text(s.sample_rate) + " Hz from " + s.rate_source +
                          "; --fs must agree with it");
  } else {
    throw usage_error(path + ": no sample rate in this " + s.format +
                      "; give --fs HZ, or a time column (t, time, time_s, Time (s), t [ms], ...)" +
                      (s.format.rfind("MATLAB", 0) == 0 ? " or a scalar variable fs" : "") +
                      (s.skipped.empty() ? "" : "; not used: " + skipped_list(s)));
  }

  out.units = choose_units(s, picked, r, out.notes);
  out.scale = r.scale;
  // Samples are scaled, not the PSD: the table then holds what it says, m/s².
  for (std::size_t c = 0; c < out.values.size(); ++c) {
    const double factor = r.scale * out.units[c].factor;
    if (factor != 1.0)
      for (double& x : out.values[c]) x *= factor;
  }
  out.unit = "m/s^2";
  return out;
}

}  // namespace rollspec::io
