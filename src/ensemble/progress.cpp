#include "src/ensemble/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace rollspec::ensemble {

Progress::Progress(std::string label, std::uint64_t total, bool quiet, std::string prefix)
    : label_(std::move(label)),
      prefix_(std::move(prefix)),
      total_(total),
      quiet_(quiet),
      tty_(::isatty(2) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::advance(std::uint64_t n) {
  const std::uint64_t done = done_ += n;
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (since < (tty_ ? 0.2 : 5.0) && done != total_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  last_ = now;
  print(done, false);
}

void Progress::finish() {
  if (quiet_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  print(done_, true);
}

void Progress::print(std::uint64_t done, bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0 ? static_cast<double>(total_ - done) / rate : 0.0;
  if (tty_) {
    const int width = 30;
    const int filled = total_ ? static_cast<int>(width * done / total_) : width;
    std::fprintf(stderr, "\r%s%s [%.*s%*s] %llu/%llu  %.1f/s  ETA %.0fs%s", prefix_.c_str(), label_.c_str(), filled,
                 "##############################", width - filled, "", static_cast<unsigned long long>(done),
                 static_cast<unsigned long long>(total_), rate, eta, final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s%s: %llu/%llu done, %.1f/s, %s %.0fs\n", prefix_.c_str(), label_.c_str(),
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_), rate,
                 final ? "took" : "ETA", final ? elapsed : eta);
  }
  std::fflush(stderr);
}

}  // namespace rollspec::ensemble
