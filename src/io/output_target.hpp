#pragma once
// Checks an output path before any work, so a run never replaces what the user did not ask it to:
//   - a directory, device, FIFO or socket (or a symbolic link to one) is refused: the
//     temporary-then-rename write would replace it with a regular file;
//   - a path that resolves to an input of the run (study, tables, signals; symlinks followed) is
//     refused;
//   - an existing regular file is replaced only if it is a rollspec output of the same kind
//     (HDF5 `filetype` attribute; a PSD CSV whose sidecar records its SHA-256, or that starts with the
//     older marker line; the sidecar of a PSD CSV), or with --force.
// Stale "<out>.tmp-<pid>" files of dead processes are removed (temp_files.hpp).
#include <string>
#include <utility>
#include <vector>

namespace rollspec::io {

// The CSV written by `rollspec psd` (no HDF5 filetype attribute): recognised by its sidecar
// `<csv>-metadata.json`, which records the CSV's SHA-256 (psd_csv.hpp), or, written before the sidecar,
// by its first line, which starts with kPsdCsvMarker ("frequency_hz,..." alone is a user's measurement).
constexpr const char* kPsdCsvKind = "rollspec-psd-csv";
constexpr const char* kPsdCsvMarker = "# rollspec-psd-csv";

struct OutputTarget {
  OutputTarget(std::string p, std::string k) : path(std::move(p)), kind(std::move(k)) {}
  std::string path;  // the path as the user gave it
  std::string kind;  // HDF5 filetype (e.g. "rollspec-result"), kPsdCsvKind or kPsdMetadataKind (psd_csv.hpp)
  std::string option = "--out";
  bool force = false;               // replace any existing regular file
  std::vector<std::string> inputs;  // files the run reads
  bool check_kind = true;           // false: only the checks that never depend on the file's contents
  bool clean_stale = true;          // remove stale temporaries (one process only, e.g. MPI rank 0)
  // An HDF5 file that HDF5 cannot open (a damaged rollspec table at its automatic name) may be
  // replaced; anything else of another kind still needs force.
  bool replace_damaged_hdf5 = false;
};

// Refuses (exit 73, or 64 for an output equal to an input) with a message naming the path, what it
// is and what is allowed. Returns the path to write: a symbolic link to a regular file is followed,
// so the link stays and its target is replaced.
std::string check_output_target(const OutputTarget& t);

// True if path is a regular HDF5 file whose root `filetype` attribute equals filetype.
bool is_rollspec_hdf5(const std::string& path, const std::string& filetype);

}  // namespace rollspec::io
