#include "src/io/provenance.hpp"

#include <fftw3.h>
#include <hdf5.h>

#include <Eigen/Core>
#include <boost/version.hpp>
#include <unistd.h>

#include <ctime>
#include <sstream>

#include "kernels/contact/version.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/version.hpp"

namespace rollspec::io {

namespace {
std::string g_command_line;

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string host_name() {
  char buf[256] = {};
  return ::gethostname(buf, sizeof buf - 1) == 0 ? std::string(buf) : std::string("unknown");
}
}  // namespace

void record_command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain =
        !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=:,+@%") ==
                          std::string::npos;
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    s += (i ? " " : "") + (plain ? a : quoted + "'");
  }
  g_command_line = s;
}

std::string library_versions() {
  unsigned maj = 0, min = 0, rel = 0;
  H5get_libversion(&maj, &min, &rel);
  std::ostringstream s;
  s << "hdf5 " << maj << "." << min << "." << rel << "; " << fftw_version << "; eigen " << EIGEN_WORLD_VERSION << "."
    << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << "; boost " << BOOST_VERSION / 100000 << "."
    << BOOST_VERSION / 100 % 1000 << "; compiler " << __VERSION__;
  return s.str();
}

std::string code_identity() {
  return std::string("rollspec ") + kVersion + "; git " + kGitSha + "; contact kernel " +
         std::to_string(contact::kernel_version);
}

void write_provenance(Hdf5Writer& w, const std::string& filetype, const std::string& schema_version,
                      const std::string& study_text, std::uint64_t seed) {
  w.attribute("/", "filetype", filetype);
  w.attribute("/", "schema_version", schema_version);
  w.attribute("/", "rollspec_version", std::string(kVersion));
  w.attribute("/", "git_sha", std::string(kGitSha));
  w.attribute("/", "library_versions", library_versions());
  w.attribute("/", "study", study_text);
  w.attribute("/", "seed", static_cast<std::int64_t>(seed));
  w.attribute("/", "rng", std::string(kRngName));
  w.attribute("/", "created", utc_now());
  w.attribute("/", "host", host_name());
  w.attribute("/", "command_line", g_command_line);
}

void check_filetype(const Hdf5Reader& r, const std::string& filetype, int schema_major) {
  if (!r.has_attribute("/", "filetype"))
    throw data_error(r.path() + ": not a rollspec file (no filetype attribute); expected filetype " + filetype);
  const std::string ft = r.string_attribute("/", "filetype");
  if (ft != filetype) throw data_error(r.path() + ": filetype is '" + ft + "'; expected '" + filetype + "'");
  const std::string v = r.string_attribute("/", "schema_version");
  const int major = std::atoi(v.c_str());
  if (major != schema_major)
    throw data_error(r.path() + ": schema_version '" + v + "' is not readable by this rollspec (reads major version " +
                     std::to_string(schema_major) + "; allowed: " + std::to_string(schema_major) + ".x)");
}

}  // namespace rollspec::io
