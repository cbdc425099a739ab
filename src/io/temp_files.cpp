#include "src/io/temp_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>

namespace fs = std::filesystem;

namespace rollspec::io {

namespace {
std::mutex g_mutex;
std::set<std::string>& registry() {
  static std::set<std::string> r;
  return r;
}
std::set<std::string>& dir_registry() {
  static std::set<std::string> r;
  return r;
}

bool process_alive(long pid) {
  if (pid <= 0) return true;  // not a pid we wrote: treat as live, keep the file
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}
}  // namespace

std::string temp_name(const std::string& final_path) { return final_path + ".tmp-" + std::to_string(::getpid()); }

namespace {
// Adds or drops `path` under the lock (the signal handler's cleanup reads the sets under it too).
void mark(std::set<std::string>& set, const std::string& path, bool held) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (held)
    set.insert(path);
  else
    set.erase(path);
}
}  // namespace

void register_temp(const std::string& path) { mark(registry(), path, true); }
void unregister_temp(const std::string& path) { mark(registry(), path, false); }
void register_temp_dir(const std::string& path) { mark(dir_registry(), path, true); }
void unregister_temp_dir(const std::string& path) { mark(dir_registry(), path, false); }

void remove_registered_temps() {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (const auto& p : registry()) ::unlink(p.c_str());
  registry().clear();
  std::error_code ec;
  for (const auto& p : dir_registry()) fs::remove_all(p, ec);
  dir_registry().clear();
}

int remove_stale_temps(const std::string& final_path) {
  const fs::path final_p(final_path);
  const fs::path dir = final_p.parent_path().empty() ? fs::path(".") : final_p.parent_path();
  const std::string prefix = final_p.filename().string() + ".tmp-";
  std::error_code ec;
  int removed = 0;
  fs::directory_iterator it(dir, ec);
  if (ec) return 0;
  for (const auto& entry : it) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()) continue;
    const long pid = std::stol(digits);
    if (pid == ::getpid() || process_alive(pid)) continue;
    if (::unlink(entry.path().c_str()) == 0) ++removed;
  }
  return removed;
}

}  // namespace rollspec::io
