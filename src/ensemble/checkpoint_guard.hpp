#pragma once
// What a run keeps beside its chunks in <out>.checkpoint/:
//   - `lock`: an flock(2) held for the whole run, so a second run on the same --out is refused
//     instead of racing on the chunks;
//   - `manifest`: the code identity (version, git sha, kernel versions), the --set overrides and
//     the resolved study the chunks belong to, with a checksum. `--resume` reruns exactly that
//     study, and refuses other settings or another build of the code.
#include <optional>
#include <string>
#include <vector>

namespace rollspec::ensemble {

struct CheckpointManifest {
  std::string identity;           // io::code_identity() of the build that wrote the chunks
  std::vector<std::string> sets;  // "section.key=value" overrides of the run (canonical values)
  std::string study_text;         // resolved study (Study::canonical_text)
  std::string study_file;         // absolute path of the study file (its directory resolves relative paths)
};

// nullopt if there is no manifest; refuses (exit 65) a damaged one, naming the file.
std::optional<CheckpointManifest> read_manifest(const std::string& directory);
void write_manifest(const std::string& directory, const CheckpointManifest& m);

// Exclusive lock on <directory>/lock (the directory is created, one level, if missing). Refuses
// (exit 73) when another process holds it, naming that run's pid.
class CheckpointLock {
 public:
  explicit CheckpointLock(const std::string& directory);
  ~CheckpointLock();
  CheckpointLock(const CheckpointLock&) = delete;
  CheckpointLock& operator=(const CheckpointLock&) = delete;
  // Removes the lock file and the directory if nothing else is left in it; then releases.
  void remove();

 private:
  std::string directory_, path_;
  int fd_ = -1;
};

// "section.key" -> value of a canonical study text ("[section]\nkey = value\n...").
std::vector<std::pair<std::string, std::string>> canonical_entries(const std::string& text);

}  // namespace rollspec::ensemble
