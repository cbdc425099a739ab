#include "src/stiffness/table_location.hpp"

#include <exception>
#include <filesystem>

#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/rank_failure.hpp"
#include "src/error.hpp"
#include "src/io/output_target.hpp"

namespace fs = std::filesystem;

namespace rollspec::stiffness {

namespace {
bool climbs(const fs::path& p) {
  for (const auto& part : p)
    if (part == "..") return true;
  return false;
}
}  // namespace

// True if `inner` (resolved, symbolic links followed as far as the path exists) lies in `outer`.
bool lies_within(const fs::path& inner, const fs::path& outer) {
  std::error_code ec;
  const fs::path a = fs::weakly_canonical(fs::absolute(inner), ec), b = fs::weakly_canonical(fs::absolute(outer), ec);
  const auto rel = a.lexically_relative(b);
  return !rel.empty() && !climbs(rel);
}

std::string prepare_table_path(const TableStore& store, const std::string& path, const std::string& filetype,
                               bool automatic) {
  const study::KeyOrigin& key = automatic ? store.table_dir_origin : store.table_origin;
  const fs::path dir = fs::path(path).parent_path();
  const fs::path table_dir(store.table_dir);
  const fs::path study_dir = fs::absolute(store.study_file).parent_path();
  // A relative table_dir is confined to the study's directory after symbolic links are resolved:
  // neither '..' nor a link out of it writes tables elsewhere. An absolute one names a shared cache
  // the user chose, and must exist.
  if (automatic && !table_dir.is_absolute() && !lies_within(dir, study_dir))
    key.refuse(
        "resolves to " + fs::weakly_canonical(fs::absolute(dir)).string() + ", outside the study's directory " +
        study_dir.string() +
        " ('..' or a symbolic link), and rollspec writes tables only below the study's directory; allowed: such a "
        "directory, or an absolute path of an existing directory");
  std::error_code ec;
  if (!dir.empty() && !fs::is_directory(dir, ec)) {
    if (fs::exists(dir, ec)) key.refuse("the table directory " + dir.string() + " is not a directory");
    if (!automatic)
      key.refuse("the table's directory " + dir.string() + " does not exist; allowed: a path in an existing directory");
    if (table_dir.is_absolute() || climbs(table_dir))
      key.refuse("the directory " + dir.string() +
                 " does not exist, and rollspec creates table directories only "
                 "below the study's directory (no '..', not absolute); create it yourself, or choose such a directory");
    fs::create_directories(dir, ec);
    if (ec)
      throw cannot_create("cannot create the table directory " + dir.string() + " (" + key.where +
                          "): " + ec.message());
  }
  io::OutputTarget target{path, filetype};
  target.option = key.where;
  // An automatic name (<table_dir>/stiffness-<input hash>.h5) is rollspec's: a table of the same
  // kind, or a damaged HDF5 file, there may be rebuilt; a file of any other kind (or a symbolic link
  // to one) is the user's and is never replaced. An explicit path is replaced only if it holds a
  // rollspec table of the same kind.
  target.replace_damaged_hdf5 = automatic;
  target.inputs = store.inputs;
  try {
    return io::check_output_target(target);
  } catch (const UserError& e) {
    throw UserError(e.exit_code(), std::string(e.what()) + " (--rebuild replaces only rollspec tables)");
  }
}

std::string table_write_path(const TableStore& store, const std::string& path, const std::string& filetype,
                             bool automatic) {
  std::string out = path;
  std::exception_ptr failure;
  if (ensemble::mpi_rank() == 0) {
    try {
      out = prepare_table_path(store, path, filetype, automatic);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  ensemble::rethrow_on_every_rank(failure, "stopped because rank 0 refused the table path (see its message)");
  return out;
}

}  // namespace rollspec::stiffness
