// rollspec: Monte-Carlo spectral studies of rolling-contact vibration.
//
//   rollspec run STUDY.ini [--out FILE.h5] [--set section.key=value ...] [--resume] [--quiet]
//   rollspec plan STUDY.ini
//   rollspec psd SIGNAL.csv --fs HZ [--segment N] [--overlap F] [--window hann|rect] [--out FILE.csv]
//   rollspec compare RESULT.h5 MEASUREMENT.csv [--sensor NAME|K | --measured-position X] [--column NAME]
//                    [--measured-averages M] [--format table|csv|json]
//   rollspec texture STUDY.ini [--out FILE.h5] [--count N]
//   rollspec modes STUDY.ini
//   rollspec stiffness STUDY.ini [--out FILE.h5] [--rebuild]
//   rollspec keys [SCENE]
//   rollspec init [SCENE] [--out FILE.ini] [--force]
//   rollspec fit STUDY.ini MEASUREMENT.csv --vary section.key=lo:hi[:log] --measured-averages M
//   rollspec version (or rollspec --version, rollspec -V)
//
// Exit codes follow <sysexits.h>: 64 usage, 65 bad data, 66 missing input, 73 cannot create
// output, 74 cannot write standard output, 78 bad configuration, 130 interrupted.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <string>

#include "src/cli/commands.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"

namespace {

const char* kUsage =
    "rollspec: Monte-Carlo spectral studies of rolling-contact vibration\n"
    "\n"
    "usage: rollspec COMMAND [ARGS] (rollspec COMMAND --help for each)\n"
    "\n"
    "commands:\n"
    "  run        run a study's ensemble and write the result file (HDF5)\n"
    "  plan       show which stages a study runs, reuses from cache, or skips, and why\n"
    "  psd        Welch PSD of a measured time series (CSV in, CSV out)\n"
    "  compare    compare a result's band levels with a measured PSD\n"
    "  fit        estimate study keys from a measured PSD, with profile-likelihood intervals\n"
    "  texture    line textures and isotropic surfaces from a roughness PSD\n"
    "  stiffness  build or reuse a contact stiffness table (elastic-plastic rough contact)\n"
    "  modes      modal frequencies of a ball-on-beam study's beam\n"
    "  keys       list the study keys of a scene with units, ranges and defaults\n"
    "  init       write a commented study of a scene to start from\n"
    "  version    print the version, git sha and library versions\n"
    "\n"
    "options:\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print the version and exit (the same as rollspec version)\n";

}  // namespace

namespace {
// Everything a command printed reaches its destination, or the command fails: a full disk or
// /dev/full behind standard output is exit 74, not a cut file and exit 0.
void check_standard_output() {
  std::cout.flush();
  errno = 0;
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (failed) {
    const int err = errno;
    std::clearerr(stdout);
    const std::string why = err ? std::strerror(err) : "the device or file refused the data (a full disk?)";
    throw rollspec::UserError(EX_IOERR, "cannot write standard output: " + why +
                                            "; the printed output is incomplete (redirect it to a disk with space)");
  }
}

// After a failed HDF5 write (a full disk) the library still holds the file whose close failed, and
// its exit-time cleanup can crash on it: report, flush, and leave without running it.
int finish(int code) {
  if (code != 0 && rollspec::io::hdf5_write_failed()) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::_exit(code);
  }
  return code;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace rollspec;
  // First: a signal from here on stops the command cleanly (exit 130), in every phase.
  ensemble::install_stop_handlers();
  if (argc < 2) {
    std::cerr << kUsage;
    return EX_USAGE;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (command == "--version" || command == "-V") return cli::version_command({});
  const std::map<std::string, int (*)(const cli::Args&)> commands = {
      {"run", cli::run_command},         {"plan", cli::plan_command},   {"psd", cli::psd_command},
      {"compare", cli::compare_command}, {"keys", cli::keys_command},   {"version", cli::version_command},
      {"texture", cli::texture_command}, {"modes", cli::modes_command}, {"stiffness", cli::stiffness_command},
      {"init", cli::init_command},       {"fit", cli::fit_command},
  };
  const auto it = commands.find(command);
  if (it == commands.end()) {
    std::cerr << "rollspec: unknown command '" << command << "'\n\n" << kUsage;
    return EX_USAGE;
  }
  const ensemble::MpiSession mpi(&argc, &argv);
  io::record_command_line(argc, argv);
  try {
    const int code = it->second(cli::Args(argv + 2, argv + argc));
    check_standard_output();
    return code;
  } catch (const UserError& e) {
    std::cerr << ensemble::rank_prefix() << "rollspec " << command << ": error: " << e.what() << "\n";
    std::cout.clear();  // what failed is reported; whatever was printed is not the error
    return finish(e.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << ensemble::rank_prefix() << "rollspec " << command
              << ": error: out of memory; the study needs more memory than is available (see rollspec plan "
                 "for the estimate; reduce the grid, duration or sample rate)\n";
    return finish(EX_OSERR);
  } catch (const std::exception& e) {
    std::cerr << "rollspec " << command << ": internal error: " << e.what() << "\n";
    return finish(EX_SOFTWARE);
  }
}
