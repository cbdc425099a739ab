#pragma once
// Per-chunk checkpoints of an ensemble: one small binary file per completed chunk of
// realisations, holding the chunk's sums, written to a temporary name and renamed, so a file
// either is complete or does not exist. A header with the study hash and a trailing FNV-1a
// checksum make a stale or damaged chunk detectable; a SIGKILLed run loses only the chunks in
// flight.
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollspec::ensemble {

// A chunk file whose values no longer match their checksum (a disk fault): recomputed, not reused.
struct DamagedChunk : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ChunkSums {
  std::uint64_t lo = 0, hi = 0;  // realisation ids [lo, hi)
  std::vector<double> values;    // sums over the chunk: [sum..., sum of squares...]
};

// Files rollspec writes in a checkpoint directory: the manifest (checkpoint_guard.hpp), the lock,
// chunk_<lo>_<hi>.bin and their temporaries. Nothing else is ever removed.
constexpr const char* kManifestName = "manifest";
constexpr const char* kLockName = "lock";
bool is_checkpoint_file_name(const std::string& name);
bool is_chunk_file(const std::string& path);  // a regular file starting with the chunk magic

class CheckpointStore {
 public:
  CheckpointStore(std::string directory, std::uint64_t study_hash);
  const std::string& directory() const { return directory_; }
  void write(const ChunkSums& chunk) const;
  // Checks every completed chunk's kind, size and header on disk and calls each(lo, hi) for it,
  // keeping none in memory (a run of 10^6 chunks resumes in constant memory) and reading no chunk's
  // values (each is read once, when the reduction reaches it). A chunk from another study (hash) or
  // of the wrong size or name is refused with exit 65 naming the file: resuming must never mix studies.
  void scan(std::size_t n_values, const std::function<void(std::uint64_t lo, std::uint64_t hi)>& each) const;
  bool has(std::uint64_t lo, std::uint64_t hi) const;
  // One chunk, read whole and checked (its checksum too) when the reduction reaches it; a chunk
  // whose bytes no longer match their checksum throws DamagedChunk (the run computes it again).
  ChunkSums read(std::uint64_t lo, std::uint64_t hi, std::size_t n_values) const;
  // Removes the files rollspec wrote (known names; chunks recognised by their magic), then the
  // directory if it is empty. The user's own files stay. keep_lock keeps the lock file (and so the
  // directory) for a run that goes on.
  void clear(bool keep_lock = false) const;
  std::vector<std::string> foreign_entries() const;  // names rollspec did not write
  std::size_t chunk_count() const;

 private:
  std::string directory_;
  std::uint64_t hash_;
};

}  // namespace rollspec::ensemble
