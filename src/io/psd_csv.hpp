#pragma once
// The PSD CSV `rollspec psd` writes, and the measured-PSD reader of `compare` and `fit`.
//
// The CSV is what pandas.read_csv(path) and numpy.genfromtxt(path, delimiter=',', names=True) read at
// their defaults: one header line `frequency_hz,<channel> [(m/s^2)^2/Hz],...` (the channel without
// its own unit: `Acc (g)` gives `Acc [(m/s^2)^2/Hz]`), then numbers. What a header cannot hold goes
// into a sidecar beside it that those readers never open, `<csv>-metadata.json` (the W3C CSVW
// convention, "Locating Metadata": `url`, `tableSchema.columns` with `titles` and `datatype`), with
// rollspec's own properties under the `rollspec:` prefix: the PSD unit, Welch segment, overlap,
// window, detrending, segments averaged and their equivalent degrees of freedom (D-16), the sample
// rate, the source file and its SHA-256, the version, and the SHA-256 of the CSV itself, so a CSV
// edited after psd wrote it is told from one psd wrote (and is then neither trusted nor replaced).
// Files written before the sidecar start with the line `# rollspec-psd-csv: ...`; both are read.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rollspec::io {

constexpr const char* kPsdUnit = "(m/s^2)^2/Hz";                   // what rollspec psd writes, and compare expects
constexpr const char* kPsdMetadataKind = "rollspec-psd-metadata";  // OutputTarget kind of the sidecar

// One PSD column as the sidecar records it.
struct PsdColumnMetadata {
  std::string title;               // its header cell: "Acc [(m/s^2)^2/Hz]"
  std::string name;                // CSVW name, an identifier: "Acc"
  std::string channel;             // the channel as the signal file named it: "Acc (g)"
  std::string signal_unit;         // the unit its samples were read in: "g", "m/s^2"
  std::string signal_unit_origin;  // where that came from: "its name", "the units row (line 2)", "--unit", "assumed"
};

// A PSD CSV's metadata (the sidecar's), and of the column read from it (read_psd_csv).
struct PsdCsvMetadata {
  std::string unit = kPsdUnit;  // PSD unit
  double sample_rate = 0.0;     // Hz
  std::string rate_source;      // "time column 'time_s'", "--fs", "the file header"
  std::size_t segment = 0;      // Welch segment, samples
  std::size_t overlap = 0;      // samples
  std::string window;           // "hann" or "rect"
  std::string detrend;          // "mean" (each segment's mean removed)
  std::size_t samples = 0;      // samples per channel
  std::size_t segments = 0;     // segments averaged
  double edof = 0.0;            // equivalent degrees of freedom of the Welch mean (D-16)
  double scale = 1.0;           // --scale
  std::string source;           // the signal file, as given to psd
  std::string source_hash;      // its SHA-256 (hex)
  std::string version;          // rollspec version and git sha that wrote it
  PsdColumnMetadata column;     // read_psd_csv: the column read; empty when the sidecar has no entry for it
};

// "<csv>-metadata.json", beside the file a symbolic link `csv_path` points to.
std::string psd_sidecar_path(const std::string& csv_path);

// Header titles of the PSD columns of these channels: the channel without its unit, then
// " [(m/s^2)^2/Hz]"; ',', ';', tab, '"' and '#' become '_'; where two would be equal, the whole channel names.
std::vector<std::string> psd_column_titles(const std::vector<std::string>& channels);

// The sidecar's JSON for the CSV text `csv` written at a path whose file name is `csv_name`.
std::string psd_sidecar_json(const PsdCsvMetadata& m, const std::vector<PsdColumnMetadata>& columns,
                             const std::string& csv_name, const std::string& csv);

// The sidecar as read: nullopt with `why` set if it is missing, no JSON, not rollspec's, or does
// not record the SHA-256 of the CSV (csv_hash; "" skips that check).
struct PsdSidecar {
  PsdCsvMetadata file;
  std::vector<PsdColumnMetadata> columns;
  std::string csv_hash;
};
std::optional<PsdSidecar> read_psd_sidecar(const std::string& sidecar_path, const std::string& csv_hash,
                                           std::string& why);

// True if `csv_path` is a PSD rollspec psd wrote and nobody edited: its sidecar is rollspec's and
// records its SHA-256, or (older files) its first line is the marker `# rollspec-psd-csv`.
bool psd_csv_written_by_rollspec(const std::string& csv_path);

// Writes the CSV and its sidecar, each to a temporary file renamed into place; an existing CSV or
// sidecar is replaced only if rollspec wrote it (above; a sidecar: rollspec's JSON), or with `force`
// (output_target.hpp for what is never replaced).
void write_psd_csv(const std::string& out, bool force, const std::vector<std::string>& inputs, const std::string& csv,
                   const PsdCsvMetadata& m, const std::vector<PsdColumnMetadata>& columns);

// A measured PSD: frequency_hz and one PSD column of a CSV, as rollspec psd writes it (either format)
// or a spreadsheet export (preamble lines, ';', decimal comma, --skip-rows, a units row).
struct PsdCsv {
  std::vector<double> frequency, psd;      // Hz, and (m/s^2)^2/Hz (converted from a g^2/Hz title)
  std::string column;                      // the header title of the column read
  std::optional<PsdCsvMetadata> metadata;  // from the sidecar, only when it records this CSV's SHA-256
  bool rollspec_output = false;            // the sidecar (verified) or the marker line says psd wrote it
  std::vector<std::string> notes;          // choices made (preamble, column, unit, sidecar ignored), one line each
};

// `column`: a header title, a title without its unit ("Acc" for "Acc [(m/s^2)^2/Hz]") or the sidecar's
// channel ("Acc (g)"); "" picks `psd`, else in rollspec's own output the only PSD column. Several
// PSD columns and no `column`: a usage error naming --column and listing them. A column whose title
// gives a unit converts from g^2/Hz (and the other acceleration units squared), or is refused.
// Errors name file, line and column (exit 65), or the option (64).
PsdCsv read_psd_csv(const std::string& path, const std::string& column, long long skip_rows);

}  // namespace rollspec::io
