#pragma once
// Provenance every rollspec output file carries (OpenMC state_point habit): file type, versioned
// schema, code version, git sha, library versions, seed, RNG and the resolved study text.
// Readers check the file type and the schema's major version before reading any data.
#include <cstdint>
#include <string>

namespace rollspec::io {

class Hdf5Writer;
class Hdf5Reader;

constexpr const char* kResultFileType = "rollspec-result";
constexpr int kResultSchemaMajor = 2;
constexpr const char* kResultSchemaVersion = "2.0";
constexpr const char* kRngName = "philox4x64-10";

std::string library_versions();

// The command line that made the files of this process, for their provenance (quoted as a shell would).
void record_command_line(int argc, char** argv);

// What a result depends on besides the study: rollspec version, git sha of the build and the kernel
// versions. Checkpoints record it, and --resume refuses chunks of another build.
std::string code_identity();

void write_provenance(Hdf5Writer& w, const std::string& filetype, const std::string& schema_version,
                      const std::string& study_text, std::uint64_t seed);

// Refuses (exit 65) a file whose filetype differs or whose schema major version is unknown.
void check_filetype(const Hdf5Reader& r, const std::string& filetype, int schema_major);

}  // namespace rollspec::io
