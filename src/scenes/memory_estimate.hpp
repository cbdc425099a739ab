#pragma once
// Up-front resource estimate of a study, from its keys alone (before any scene object, FFT plan or
// workspace is allocated): peak memory and checkpoint disk. `rollspec plan` prints it; `run`,
// `texture` and `stiffness` refuse a study whose memory estimate exceeds the memory available
// (MemAvailable, the address-space limit and the cgroup limit), unless --force, naming the keys
// that drive it. The figures are calibrated against measured peaks (ru_maxrss) and err high.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

struct MemoryEstimate {
  double bytes = 0.0;             // estimated peak resident memory
  std::vector<std::string> keys;  // the keys that drive it, as "[section] key = value"
  std::string what;               // the largest item, in words
  // Every term that grows with the keys, in words, and its bytes (the process baseline aside).
  std::vector<std::pair<std::string, double>> terms;
};

// One term of a scene's memory model: its bytes, the keys that drive it and what it is, in words.
struct MemoryItem {
  double bytes;
  std::vector<std::string> keys;
  std::string what;
};

// `threads`: OpenMP threads that each hold a workspace; the terms are the study's scene's (find_scene).
MemoryEstimate estimate_memory(const study::KeyReader& s, int threads);

// "1.5 GiB" etc.
std::string format_bytes(double bytes);

// Refuses (exit 78) a study whose estimate exceeds io::available_memory(), naming the keys, unless
// `force`.
void check_memory(const study::KeyReader& s, int threads, bool force);

}  // namespace rollspec::scenes
