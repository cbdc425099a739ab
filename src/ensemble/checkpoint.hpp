#pragma once
// Per-chunk checkpoints of an ensemble: one small binary file per completed chunk of
// realisations, holding the chunk's sums, written to a temporary name and renamed, so a file
// either is complete or does not exist. A header with the study hash and a trailing FNV-1a
// checksum make a stale or damaged chunk detectable; a SIGKILLed run loses only the chunks in
// flight.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rollspec::ensemble {

struct ChunkSums {
  std::uint64_t lo = 0, hi = 0;   // realisation ids [lo, hi)
  std::vector<double> values;     // sums over the chunk: [sum..., sum of squares...]
};

std::uint64_t fnv1a64(const void* data, std::size_t n, std::uint64_t h = 14695981039346656037ull);
std::uint64_t fnv1a64(const std::string& s);

class CheckpointStore {
 public:
  CheckpointStore(std::string directory, std::uint64_t study_hash);
  const std::string& directory() const { return directory_; }
  void write(const ChunkSums& chunk) const;
  // Completed chunks on disk, keyed by lo. A chunk from another study (hash) or a damaged file is
  // refused with exit 65 naming the file: resuming must never mix studies.
  std::map<std::uint64_t, ChunkSums> load(std::size_t n_values) const;
  void clear() const;  // removes the directory (fresh run, or after the result is committed)

 private:
  std::string directory_;
  std::uint64_t hash_;
};

}  // namespace rollspec::ensemble
