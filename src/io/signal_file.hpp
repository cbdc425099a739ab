#pragma once
// Measured time signals for `rollspec psd`: CSV/text, sound files (libsndfile: WAV, FLAC, AIFF, ...)
// and MATLAB .mat (matio: v4, v5, v7.3), chosen by content, else by extension, else text.
// Every reader yields a SignalTable; prepare_signal() then picks channels, settles the sample rate
// and converts to m/s². Errors name the file and the line, variable or channel at fault (exit 65),
// a bad option (64) or a missing file (66).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rollspec::io {

// Where a channel's unit came from.
enum class UnitOrigin {
  none,       // readers: the file says nothing
  name,       // the column or variable name: `Acc (g)`, `a [m/s²]`, `acc_g`
  units_row,  // a CSV units row: `[s]⇥[m/s²]` under the header
  option,     // --unit
  assumed     // prepare_signal: nothing said it, taken as m/s² (said in a note naming --unit)
};

// The unit a channel's values are in (before --scale), and where that came from.
struct ChannelUnit {
  std::string text;     // canonical: "g", "m/s^2", "mm/s^2"; a unit that is no acceleration as written ("V")
  std::string written;  // as the file or --unit wrote it ("g", "m/s²", "[mm/s^2]"); "" if none
  double factor = 0.0;  // m/s² per unit (9.80665 for g); 0: no unit found, or no acceleration
  UnitOrigin origin = UnitOrigin::none;
  std::string where;     // for messages: "its name", "the units row (line 3)", "--unit", "assumed"
  std::string conflict;  // readers: name and units row disagree (the refusal, unless --unit decides)
};

struct SignalTable {
  std::string file;
  std::string format;                 // for messages: "CSV text (semicolon-delimited, decimal comma)"
  std::vector<std::string> channels;  // names, file order
  std::vector<std::string> groups;  // what each channel came from: the .mat variable of a matrix column, else its name
  std::vector<std::vector<double>> values;  // values[channel][sample]; .mat channels may differ in length until picked
  double sample_rate = 0.0;                 // Hz; 0 if the file does not say
  std::string rate_source;                  // where sample_rate came from: "time column 'time_s'", "the file header"
  std::string time_column;                  // the time column or variable, never a channel ("" if none)
  std::size_t time_samples = 0;             // its length (a .mat time vector must match the channels)
  std::string unit;                         // unit of values: "as stored", "full scale" (integer PCM), then "m/s^2"
  std::vector<ChannelUnit> units;           // one per channel: what the file says (readers), then what was used
  double scale = 1.0;                       // prepare_signal: --scale, applied with the unit's factor
  std::vector<std::pair<std::string, std::string>> skipped;  // .mat variables that are not channels, and why
  std::vector<std::string> notes;  // choices made without being asked (delimiter, header, rate), one line each

  std::size_t samples() const { return values.empty() ? 0 : values.front().size(); }
};

struct SignalRequest {
  std::vector<std::string> columns;  // --column values (each a name, or comma-separated names); empty: all channels
  double fs = 0.0;                   // --fs; 0: from the file. Overrides a CSV time column (with a note).
  std::string unit;                  // --unit: one unit for all picked channels or one each, comma-separated;
                                     // "": each channel's from the file, else m/s² (said)
  double scale = 1.0;                // --scale: physical units (of --unit) per file unit / per full scale
  bool scale_given = false;          // integer PCM needs it: full scale is no physical unit
  std::string time_column;           // --time-column: "" (by name), "none", or the column to use
  long long skip_rows = -1;          // --skip-rows: lines before a CSV header; -1: found from the data
};

// Readers, one per family (signal_csv.cpp, signal_sound.cpp, signal_mat.cpp). The path exists and is a
// regular file.
SignalTable read_csv_signal(const std::string& path, const SignalRequest& request = {});
SignalTable read_sound_signal(const std::string& path);
SignalTable read_mat_signal(const std::string& path, const SignalRequest& request = {});

// Any of the above, by content (RIFF/FORM/fLaC/OggS/.snd magic, "MATLAB" header), else by extension
// (.wav .flac .aif(f) .au .ogg .caf .w64 .rf64: sound; .mat: MATLAB), else text.
// Options a file kind has no use for are refused: --skip-rows except for CSV, --time-column NAME for
// sound files.
SignalTable read_signal(const std::string& path, const SignalRequest& request = {});

constexpr double kStandardGravity = 9.80665;  // m/s² per g, exact (CGPM 1901)

// Accepted --unit values, for messages.
constexpr const char* kSignalUnits =
    "g, m/s2 (also m/s^2), cm/s2, mm/s2, um/s2, in/s2 or ft/s2, one for all channels or one per channel (g,m/s2)";

// Reads `path` and returns the picked channels, all of one length, in m/s², with sample_rate set (the
// file's, or --fs where they agree within kRateTolerance, or --fs alone) and `units` saying what each
// channel was read in: --unit, else the file's (name, units row), else m/s² (assumed). A channel whose
// file unit is known to be no acceleration (V, N, ...) is refused unless --unit. Each choice is a note.
SignalTable prepare_signal(const std::string& path, const SignalRequest& request);

// --unit's units: one for every channel, or one per picked channel in their order ("g,m/s^2"); refuses
// (usage) what is no acceleration unit.
std::vector<ChannelUnit> option_units(const std::string& units);

// The units of the channels `picked` of a reader's table (signal_units.cpp): --unit, else the file's,
// else m/s² (assumed), each choice a line in `notes`. Refuses a channel in a unit that is no acceleration.
std::vector<ChannelUnit> choose_units(const SignalTable& s, const std::vector<std::size_t>& picked,
                                      const SignalRequest& request, std::vector<std::string>& notes);

}  // namespace rollspec::io
