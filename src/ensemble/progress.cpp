#include "src/ensemble/progress.hpp"
#include "src/io/number_text.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace rollspec::ensemble {

namespace {

// Columns of the terminal on stderr (80 when it cannot say).
int terminal_columns() {
  winsize w{};
  return ::ioctl(2, TIOCGWINSZ, &w) == 0 && w.ws_col > 0 ? w.ws_col : 80;
}

std::string seconds_text(double s) {
  if (s < 60) return io::formatted("%.0fs", s);
  if (s < 3600) return io::formatted("%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return io::formatted("%dh%02dm", static_cast<int>(s) / 3600, static_cast<int>(s) / 60 % 60);
}

}  // namespace

Progress::Progress(std::string label, std::uint64_t total, bool quiet, std::string prefix)
    : label_(std::move(label)),
      prefix_(std::move(prefix)),
      total_(total),
      quiet_(quiet),
      tty_(::isatty(2) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

Progress::~Progress() {
  // Interrupted (an exception unwinds past the loop): end the bar's line, so the error that follows
  // starts on a line of its own.
  if (tty_ && on_screen_ && !finished_) {
    std::fputs("\n", stderr);
    std::fflush(stderr);
  }
}

void Progress::advance(std::uint64_t n) {
  const std::uint64_t done = done_ += n;
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (since < (tty_ ? 0.2 : 5.0) && done != total_) return;
  if (!tty_ && done == total_) return;  // a log gets one final line, from finish()
  if (!shown_ && std::chrono::duration<double>(now - start_).count() < show_after_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  last_ = now;
  print(done, false);
}

void Progress::finish() {
  if (quiet_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  if (!shown_ && std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() < show_after_) return;
  print(done_, true);
  finished_ = true;
}

void Progress::print(std::uint64_t done, bool final) {
  shown_ = true;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0 ? static_cast<double>(total_ - done) / rate : 0.0;
  const std::string counts = io::formatted("%llu/%llu  %.1f/s  %s %s", static_cast<unsigned long long>(done),
                                           static_cast<unsigned long long>(total_), rate, final ? "took" : "ETA",
                                           seconds_text(final ? elapsed : eta).c_str());
  if (!tty_) {
    std::fprintf(stderr, "%s%s: %s\n", prefix_.c_str(), label_.c_str(), counts.c_str());
    std::fflush(stderr);
    return;
  }
  // The line never reaches the last column (no wrap, no scrolling); the bar takes what is left, up
  // to 30 characters, and is left out below 10; the label is cut last. "\r" then "\x1b[K" clears
  // what a longer previous line left.
  const int columns = terminal_columns() - 1;
  std::string head = prefix_ + label_;
  const int fixed = static_cast<int>(head.size() + 1 + std::string(counts).size());
  const int bar = std::min(30, columns - fixed - 3);
  std::string line = head;
  if (bar >= 10) {
    const int filled = total_ ? static_cast<int>(static_cast<std::uint64_t>(bar) * done / total_) : bar;
    line += " [" + std::string(static_cast<std::size_t>(filled), '#') +
            std::string(static_cast<std::size_t>(bar - filled), ' ') + "]";
  }
  line += " ";
  line += counts;
  if (static_cast<int>(line.size()) > columns) line.resize(static_cast<std::size_t>(std::max(columns, 0)));
  std::fprintf(stderr, "\r%s\x1b[K%s", line.c_str(), final ? "\n" : "");
  on_screen_ = !final;
  std::fflush(stderr);
}

}  // namespace rollspec::ensemble
