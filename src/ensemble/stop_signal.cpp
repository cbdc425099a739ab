#include "src/ensemble/stop_signal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

#include "src/error.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::ensemble {

namespace {
volatile std::sig_atomic_t g_stop = 0;
volatile std::sig_atomic_t g_signal = 0;
int g_pipe[2] = {-1, -1};
std::atomic<int> g_critical{0};
std::atomic<bool> g_installed{false};

// The ensemble loop stops within one realisation; any other phase is ended after this grace.
constexpr auto kGrace = std::chrono::milliseconds(400);

extern "C" void on_stop_signal(int sig) {
  const int saved = errno;
  g_signal = sig;
  g_stop = 1;
  if (g_pipe[1] >= 0) {
    const char b = 1;
    [[maybe_unused]] const auto n = ::write(g_pipe[1], &b, 1);
  }
  errno = saved;
}

void write_stderr(const char* s) { [[maybe_unused]] const auto n = ::write(2, s, std::strlen(s)); }

void watchdog() {
  char b = 0;
  while (::read(g_pipe[0], &b, 1) < 0 && errno == EINTR) {
  }
  const auto deadline = std::chrono::steady_clock::now() + kGrace;
  while (std::chrono::steady_clock::now() < deadline || g_critical.load() > 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  io::remove_registered_temps();
  const int sig = g_signal;
  write_stderr(sig == SIGHUP    ? "rollspec: interrupted (SIGHUP)"
               : sig == SIGTERM ? "rollspec: interrupted (SIGTERM)"
                                : "rollspec: interrupted (SIGINT)");
  write_stderr(
      ": stopped; completed stage tables and checkpointed chunks are kept, no partial file was "
      "written; rerun the same command (run: add --resume) to continue\n");
  ::_exit(kExitInterrupted);
}
}  // namespace

void install_stop_handlers() {
  if (g_installed.exchange(true)) return;
  if (::pipe2(g_pipe, O_CLOEXEC) == 0) std::thread(watchdog).detach();
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
}

bool stop_requested() { return g_stop != 0; }
void request_stop() { g_stop = 1; }
void clear_stop() { g_stop = 0; }

CriticalSection::CriticalSection() { ++g_critical; }
CriticalSection::~CriticalSection() { --g_critical; }

}  // namespace rollspec::ensemble
