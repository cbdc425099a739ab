// Writing a PSD CSV and its sidecar (psd_csv.hpp): both checked before either is written, each written
// beside its place and renamed onto it, so an existing file is replaced whole or not at all and no
// temporary file outlives a failure.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/output_target.hpp"
#include "src/io/psd_csv.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::io {

namespace {
struct Pending {
  std::string out, path, tmp;
};

[[noreturn]] void fail(const std::vector<Pending>& files, const std::string& what, int err) {
  for (const auto& f : files) {
    std::remove(f.tmp.c_str());
    unregister_temp(f.tmp);
  }
  throw cannot_create(what + " (" + (err == ENOSPC ? std::string("no space left on device") : std::strerror(err)) +
                      ")");
}

void put(std::vector<Pending>& files, const Pending& f, const std::string& text) {
  register_temp(f.tmp);
  files.push_back(f);
  errno = 0;
  std::ofstream o(f.tmp, std::ios::trunc | std::ios::binary);
  if (!o) fail(files, "cannot create output file '" + f.out + "' (writing " + f.tmp + ")", errno ? errno : EIO);
  o << text;
  o.close();
  if (!o) fail(files, "cannot write output file '" + f.out + "' (writing " + f.tmp + ")", errno ? errno : EIO);
}
}  // namespace

void write_psd_csv(const std::string& out, bool force, const std::vector<std::string>& inputs, const std::string& csv,
                   const PsdCsvMetadata& m, const std::vector<PsdColumnMetadata>& columns) {
  OutputTarget target{out, kPsdCsvKind};
  target.force = force;
  target.inputs = inputs;
  const std::string csv_path = check_output_target(target);
  OutputTarget side{psd_sidecar_path(csv_path), kPsdMetadataKind};
  side.force = force;
  side.inputs = inputs;
  const std::string side_path = check_output_target(side);
  const std::string name = std::filesystem::path(csv_path).filename().string();
  std::vector<Pending> files;
  put(files, {out, csv_path, temp_name(csv_path)}, csv);
  put(files, {side.path, side_path, temp_name(side_path)}, psd_sidecar_json(m, columns, name, csv));
  // The CSV first: should the sidecar's rename fail, the new CSV has no sidecar recording it and is
  // protected like a user's file, never replaced in silence.
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(files[i].tmp, files[i].path, ec);
    if (ec)
      fail({files.begin() + static_cast<std::ptrdiff_t>(i), files.end()},
           "cannot create output file '" + files[i].out + "': " + ec.message(), ec.value());
    unregister_temp(files[i].tmp);
  }
}

}  // namespace rollspec::io
