#include "src/io/output_target.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/input_file.hpp"
#include "src/io/psd_csv.hpp"
#include "src/io/temp_files.hpp"

namespace fs = std::filesystem;

namespace rollspec::io {

namespace {

bool is_psd_sidecar(const std::string& path) {
  std::string why;
  return read_psd_sidecar(path, "", why).has_value();
}

bool same_kind(const std::string& path, const std::string& kind) {
  if (kind == kPsdCsvKind) return psd_csv_written_by_rollspec(path);
  if (kind == kPsdMetadataKind) return is_psd_sidecar(path);
  return is_rollspec_hdf5(path, kind);
}

// HDF5's format signature at offset 0, and HDF5 itself cannot open the file.
bool is_damaged_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  if (in.gcount() != 8 || std::string(head, 8) != std::string("\x89HDF\r\n\x1a\n", 8)) return false;
  try {
    const Hdf5Reader r(path);
    return false;
  } catch (const UserError&) {
    return true;
  }
}

std::string kind_description(const std::string& kind, const std::string& path) {
  if (kind == kPsdCsvKind)
    return "a PSD written by rollspec psd and not edited since (its sidecar " + psd_sidecar_path(path) +
           " would record the file's SHA-256)";
  if (kind == kPsdMetadataKind) return "the metadata of a PSD written by rollspec psd";
  return "a rollspec file of filetype '" + kind + "'";
}
}  // namespace

bool is_rollspec_hdf5(const std::string& path, const std::string& filetype) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  try {
    const Hdf5Reader r(path);
    return r.has_attribute("/", "filetype") && r.string_attribute("/", "filetype") == filetype;
  } catch (const UserError&) {
    return false;
  }
}

std::string check_output_target(const OutputTarget& t) {
  const std::string& out = t.path;
  struct stat lst {
  }, st{};
  if (::lstat(out.c_str(), &lst) != 0) {
    if (t.clean_stale) remove_stale_temps(out);
    return out;  // nothing there: created fresh
  }
  const bool link = S_ISLNK(lst.st_mode);
  if (::stat(out.c_str(), &st) != 0)
    throw cannot_create("cannot create output file '" + out + "' (" + t.option +
                        "): it is a symbolic link to a missing file; allowed: a new path or a regular file");
  if (!S_ISREG(st.st_mode))
    throw cannot_create("cannot create output file '" + out + "' (" + t.option + "): it is " +
                        (link ? std::string("a symbolic link to ") : std::string()) + file_kind(st.st_mode) +
                        "; rollspec writes regular files only and never replaces a directory, device, FIFO or "
                        "socket; choose another " +
                        t.option);
  std::error_code ec;
  for (const auto& in : t.inputs) {
    if (in.empty() || !fs::exists(in, ec)) continue;
    if (fs::equivalent(out, in, ec))
      throw usage_error(t.option + " " + out + " is also an input of this command ('" + in +
                        "'); refusing to overwrite an input; choose another " + t.option);
  }
  if (t.check_kind && !same_kind(out, t.kind) && !t.force && !(t.replace_damaged_hdf5 && is_damaged_hdf5(out)))
    throw cannot_create("output file '" + out + "' (" + t.option + ") exists and is not " +
                        kind_description(t.kind, out) + "; refusing to replace it; choose another " + t.option +
                        (t.option.rfind("--", 0) == 0 ? ", or add --force to replace it" : ""));
  const std::string target = link ? fs::canonical(out, ec).string() : out;
  if (ec) throw cannot_create("cannot resolve the symbolic link '" + out + "': " + ec.message());
  if (t.clean_stale) remove_stale_temps(target);
  return target;
}

}  // namespace rollspec::io
