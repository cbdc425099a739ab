// Which reader a signal file needs: its first bytes, else its extension, else text.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/input_file.hpp"
#include "src/io/provenance.hpp"
#include "src/io/signal_file.hpp"

namespace rollspec::io {

namespace {
enum class Family { text, sound, mat };

// Magic numbers checked far enough that a text header (say "RIFFLE;acc") is not taken for sound.
Family by_content(const std::string& head) {
  const auto at = [&](std::size_t pos, const char* magic) { return head.compare(pos, std::strlen(magic), magic) == 0; };
  for (const char* riff : {"RIFF", "RIFX", "RF64"})
    if (at(0, riff) && at(8, "WAVE")) return Family::sound;
  if (at(0, "FORM") && (at(8, "AIFF") || at(8, "AIFC"))) return Family::sound;
  for (const char* magic : {"fLaC", "OggS", ".snd", "caff", "riff."})
    if (at(0, magic)) return Family::sound;
  if (head.compare(0, 6, "MATLAB") == 0) return Family::mat;  // v5 and v7.3 headers; v4 has none
  return Family::text;
}

// HDF5 (signature at 0, or after a 512-byte user block) that is no MATLAB v7.3 file: rollspec's own
// files, or another program's; refused in one line saying what reads it.
bool is_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string signature("\x89HDF\r\n\x1a\n", 8);
  for (const std::streamoff at : {0, 512}) {
    std::string head(8, '\0');
    in.clear();
    in.seekg(at);
    in.read(head.data(), 8);
    if (in.gcount() == 8 && head == signature) return true;
  }
  return false;
}

[[noreturn]] void refuse_hdf5(const std::string& path) {
  std::string filetype;
  try {
    const Hdf5Reader r(path);
    if (r.has_attribute("/", "filetype")) filetype = r.string_attribute("/", "filetype");
  } catch (const UserError&) {
  }
  const std::string reads = "; rollspec psd reads measured signals (CSV/text, WAV/FLAC, .mat)";
  if (filetype == kResultFileType)
    throw data_error(path + ": a rollspec result (HDF5), not a measured signal: `rollspec compare " + path +
                     " MEASUREMENT` compares it with a measurement, `python3 -m rollspec_post psd " + path +
                     " --out PICTURE.png` plots its PSD" + reads);
  if (filetype.rfind("rollspec-", 0) == 0)
    throw data_error(path + ": a rollspec file of filetype '" + clip(filetype) + "' (HDF5), not a measured signal" +
                     reads);
  throw data_error(path +
                   ": an HDF5 file, not a measured signal (a MATLAB v7.3 file starts with its 'MATLAB' "
                   "header)" +
                   reads);
}

Family by_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".mat") return Family::mat;
  for (const char* e :
       {".wav", ".wave", ".flac", ".aif", ".aiff", ".aifc", ".au", ".snd", ".ogg", ".oga", ".caf", ".w64", ".rf64"})
    if (ext == e) return Family::sound;
  return Family::text;
}
}  // namespace

SignalTable read_signal(const std::string& path, const SignalRequest& request) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw missing_input("cannot read '" + path +
                        "': it is a directory; expected a signal file (CSV/text, WAV/FLAC, .mat)");
  require_regular_input(path, "signal file (CSV file, sound file or .mat)");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw missing_input("cannot open '" + path + "': " + (errno ? std::strerror(errno) : "no such file") +
                        "; expected a signal file (CSV/text, WAV/FLAC, .mat)");
  char head[12] = {};
  in.read(head, sizeof head);
  Family family = by_content(std::string(head, static_cast<std::size_t>(in.gcount())));
  if (family == Family::text && is_hdf5(path)) refuse_hdf5(path);
  if (family == Family::text) family = by_extension(path);
  if (family != Family::text && request.skip_rows >= 0)
    throw usage_error("--skip-rows: '" + path + "' is a " + (family == Family::sound ? "sound" : "MATLAB .mat") +
                      " file, not CSV text; allowed: --skip-rows with CSV/text files only");
  if (family == Family::sound && !request.time_column.empty() && request.time_column != "none")
    throw usage_error(
        "--time-column " + clip(request.time_column) + ": '" + path +
        "' is a sound file (its rate is in the header, it has no time column); allowed: --time-column with "
        "CSV/text and .mat files");
  switch (family) {
    case Family::sound:
      return read_sound_signal(path);
    case Family::mat:
      return read_mat_signal(path, request);
    case Family::text:
      break;
  }
  return read_csv_signal(path, request);
}

}  // namespace rollspec::io
