#include "src/stiffness/table_location.hpp"

#include <exception>
#include <filesystem>

#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"
#include "src/io/output_target.hpp"
#include "src/study/study.hpp"
#include "src/texture/texture_keys.hpp"

namespace fs = std::filesystem;

namespace rollspec::stiffness {

namespace {
bool climbs(const fs::path& p) {
  for (const auto& part : p)
    if (part == "..") return true;
  return false;
}
}  // namespace

std::string prepare_table_path(const study::Study& s, const std::string& path, const std::string& filetype,
                               bool automatic) {
  const std::string key = automatic ? "stiffness.table_dir" : "stiffness.table";
  const fs::path dir = fs::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty() && !fs::is_directory(dir, ec)) {
    if (fs::exists(dir, ec)) s.refuse(key, "the table directory " + dir.string() + " is not a directory");
    const fs::path table_dir(s.text("stiffness.table_dir"));
    if (!automatic)
      s.refuse(key, "the table's directory " + dir.string() + " does not exist; allowed: a path in an existing directory");
    if (table_dir.is_absolute() || climbs(table_dir))
      s.refuse(key, "the directory " + dir.string() + " does not exist, and rollspec creates table directories only "
                    "below the study's directory (no '..', not absolute); create it yourself, or choose such a directory");
    fs::create_directories(dir, ec);
    if (ec) throw cannot_create("cannot create the table directory " + dir.string() + " (" + s.where(key) + "): " + ec.message());
  }
  io::OutputTarget target{path, filetype};
  target.option = s.where(key);
  // An automatic name (<table_dir>/stiffness-<input hash>.h5) is rollspec's own: a damaged table
  // there may be rebuilt. An explicit path is replaced only if it holds a rollspec table.
  target.force = automatic;
  target.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(s)) target.inputs.push_back(p);
  try {
    return io::check_output_target(target);
  } catch (const UserError& e) {
    throw UserError(e.exit_code(), std::string(e.what()) + " (--rebuild replaces only rollspec tables)");
  }
}

std::string table_write_path(const study::Study& s, const std::string& path, const std::string& filetype,
                             bool automatic) {
  std::string out = path;
  std::exception_ptr failure;
  if (ensemble::mpi_rank() == 0) {
    try {
      out = prepare_table_path(s, path, filetype, automatic);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  const bool failed_somewhere = ensemble::any_rank(failure != nullptr);
  if (failure) std::rethrow_exception(failure);
  if (failed_somewhere)
    throw UserError(EX_SOFTWARE, "stopped because rank 0 refused the table path (see its message)");
  return out;
}

}  // namespace rollspec::stiffness
