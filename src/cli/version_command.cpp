// rollspec version: code version, git sha, schema and library versions.
#include <iostream>

#include "src/cli/commands.hpp"
#include "src/io/provenance.hpp"
#include "src/version.hpp"

namespace rollspec::cli {

int version_command(const Args&) {
  std::cout << "rollspec " << kVersion << " (git " << kGitSha << ")\n"
            << "result schema " << io::kResultSchemaVersion << ", rng " << io::kRngName << "\n"
            << io::library_versions() << "\n";
  return 0;
}

}  // namespace rollspec::cli
