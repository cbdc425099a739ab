#include "src/scenes/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/error.hpp"
#include "src/io/available_memory.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::scenes {

namespace {

// The process itself: libraries, HDF5, FFTW wisdom (measured: 25-27 MiB peak for small studies,
// bench/engine/bench_memory_estimate.py).
constexpr double kBaseline = 28.0 * 1024 * 1024;

}  // namespace

MemoryEstimate estimate_memory(const study::KeyReader& s, int threads) {
  MemoryEstimate e;
  e.bytes = kBaseline;
  double largest = -1.0;
  const auto& memory = find_scene(s.scene()).memory;
  for (const auto& it : memory ? memory(s, threads) : std::vector<MemoryItem>{}) {
    e.bytes += it.bytes;
    e.terms.emplace_back(it.what, it.bytes);
    if (it.bytes > largest) {
      largest = it.bytes;
      e.keys = it.keys;
      e.what = it.what;
    }
  }
  return e;
}

std::string format_bytes(double b) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (b >= 1024.0 && u < 5) b /= 1024.0, ++u;
  return io::formatted(u ? "%.3g %s" : "%.0f %s", b, units[u]);
}

void check_memory(const study::KeyReader& s, int threads, bool force) {
  const MemoryEstimate e = estimate_memory(s, threads);
  const double available = io::available_memory();
  if (force || !(e.bytes > available)) return;
  std::string keys;
  for (const auto& k : e.keys) keys += (keys.empty() ? "" : ", ") + k;
  throw config_error(
      s.file() + ": the study needs an estimated " + format_bytes(e.bytes) + " of memory (largest: " + e.what +
      ", from " + keys + ", " + std::to_string(threads) + " thread(s)), but only " + format_bytes(available) +
      " is available; allowed: a smaller value of these keys, fewer threads (OMP_NUM_THREADS), or --force "
      "to try anyway");
}

}  // namespace rollspec::scenes
