#pragma once
// Progress of a long loop on stderr: a bar with rate and ETA on a terminal (fitted to its width,
// ended by a "took" line, its line closed if the loop is interrupted), a log line every few
// seconds otherwise, nothing when quiet. Safe to call from several threads.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace rollspec::ensemble {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total, bool quiet, std::string prefix = "");
  // Shows nothing (not even the final line) unless the loop is still running after `seconds`:
  // for phases that are usually quick.
  void show_after(double seconds) { show_after_ = seconds; }
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void advance(std::uint64_t n = 1);
  void finish();

 private:
  void print(std::uint64_t done, bool final);
  std::string label_, prefix_;
  std::uint64_t total_;
  bool quiet_, tty_;
  bool on_screen_ = false, finished_ = false, shown_ = false;
  double show_after_ = 0.0;
  std::atomic<std::uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mutex_;
};

}  // namespace rollspec::ensemble
