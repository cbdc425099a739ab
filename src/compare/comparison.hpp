#pragma once
// rollspec compare as an engine function: a result file and a measurement (recordings, or one PSD table)
// in, the whole verdict out (design §7, "the verdict has two ends"). The command (cli/compare_command.cpp)
// and the Python module (rollspec.studies.compare) read their options into a CompareRequest and print or
// return the Comparison; comparison_json.hpp gives its JSON. Everything is computed before anything is
// returned, so a refused input leaves no partial answer.
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "src/compare/band_verdict.hpp"
#include "src/compare/measured_spectrum.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::compare {

// The command's options, by their names (--fmin, --noise-margin, ...); an empty optional is an option not
// given. The refusals name the option as the command spells it.
struct CompareRequest {
  std::string result;                       // the result file (HDF5)
  std::vector<std::string> measurements;    // recordings, one file per roll, or one PSD table
  std::string noise;                        // --noise: the rig at rest, a recording or its PSD table ("": none)
  std::string sensor;                       // --sensor: a name or K of sensor_K ("": sensor_mean, else the first)
  std::optional<double> measured_position;  // --measured-position, m
  std::string point;                        // --point: K or section.key=value[,...] of a sweep result
  std::vector<std::string> columns;         // --column: the recordings' channels, or one PSD table column
  std::string unit;                         // --unit ("": from the file)
  std::optional<double> scale;              // --scale
  std::optional<double> fs;                 // --fs, Hz
  std::string time_column;                  // --time-column ("": by name; "none")
  std::optional<long long> skip_rows;       // --skip-rows
  bool roll_per_channel = false;            // --roll-per-channel
  std::optional<double> measured_averages;  // --measured-averages M
  double noise_margin_db = 10.0;            // --noise-margin
  bool keep_floor_bands = false;            // --keep-floor-bands
  bool same_surface = false;                // --same-surface
  double fmin = 0.0, fmax = INFINITY;       // --fmin, --fmax, Hz
  double test_level = 0.05;                 // --test-level
  // Where the choices made reading a PSD table (its preamble, column, unit) go as it is read: the command
  // prints them at once, so they precede a later refusal. Unset: they open Comparison::messages.
  std::function<void(const std::string&)> reading_note;
};

// The result's loss of contact (ball-on-beam): its share and what `run` wrote of it.
struct LossOfContact {
  double share = NAN;         // NaN: the result does not record it
  std::string warning, note;  // a warning where it moved bands (D-35), else a note of its share
};

struct CitedReference {
  std::string id, citation, doi;
};

struct Comparison {
  std::string result;    // the path as given
  io::BandLevels bands;  // the result's row compared
  MeasuredSpectrum measurement;
  std::optional<MeasuredSpectrum> noise;  // --noise through the same estimator, or its PSD table
  bool psd_table = false;                 // the measurement is a PSD table, not recordings
  std::string column;                     // the PSD table's column read, or the one --column ("": none)
  Verdict verdict;
  LossOfContact loss;
  bool has_interval = false;  // the result has enough realisations for an interval of its mean
  bool predict = false;       // M is known and has_interval: prediction intervals and the combined test
  // The result's references (/provenance/references), then the verdict's own, each once.
  std::vector<CitedReference> references;
  // What the command says on stderr, in its order, one line each ("WARNING: " where it is one): the
  // choices made reading a PSD table (unless reading_note took them), how the row was picked, the measurement's notes,
  // the result's loss of contact, a table error left out, and the verdict's warnings.
  std::vector<std::string> messages;
};

// Refuses (exit 64) a bad option value before any file is read, naming the option and what is allowed;
// refuses missing or unreadable inputs (66) and results or measurements that cannot be compared (64, 65)
// with the command's one-line messages.
Comparison compare_result(const CompareRequest& request);

}  // namespace rollspec::compare
