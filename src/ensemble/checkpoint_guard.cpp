#include "src/ensemble/checkpoint_guard.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/ensemble/checkpoint.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/temp_files.hpp"

namespace fs = std::filesystem;

namespace rollspec::ensemble {

namespace {
constexpr const char* kHeader = "rollspec checkpoint manifest 1\n";
constexpr std::size_t kMaxManifestBytes = 16u << 20;

std::string body_of(const CheckpointManifest& m) {
  std::ostringstream s;
  s << kHeader << "identity = " << m.identity << "\n";
  if (!m.study_file.empty()) s << "study_file = " << m.study_file << "\n";
  for (const auto& set : m.sets) s << "set = " << set << "\n";
  s << "study:\n" << m.study_text << "end of study\n";
  return s.str();
}
}  // namespace

std::vector<std::pair<std::string, std::string>> canonical_entries(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(text);
  std::string line, section;
  while (std::getline(in, line)) {
    if (line.size() >= 2 && line.front() == '[' && line.back() == ']') {
      section = line.substr(1, line.size() - 2);
      continue;
    }
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    out.emplace_back(section + "." + line.substr(0, eq), line.substr(eq + 3));
  }
  return out;
}

std::optional<CheckpointManifest> read_manifest(const std::string& directory) {
  const std::string path = (fs::path(directory) / kManifestName).string();
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return std::nullopt;
  if (!S_ISREG(st.st_mode) || static_cast<std::size_t>(st.st_size) > kMaxManifestBytes)
    throw data_error(path + ": not a checkpoint manifest rollspec wrote (not a regular file, or too large)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  const auto damaged = [&](const std::string& why) {
    return data_error(path + ": damaged checkpoint manifest (" + why + "); start over with --restart");
  };
  const auto tail = text.rfind("checksum = ");
  if (text.compare(0, std::strlen(kHeader), kHeader) != 0 || tail == std::string::npos) throw damaged("header");
  const std::string body = text.substr(0, tail);
  if (text.substr(tail) != "checksum = " + io::hex16(io::fnv1a64(body)) + "\n") throw damaged("checksum");
  CheckpointManifest m;
  std::istringstream lines(body.substr(std::strlen(kHeader)));
  std::string line;
  while (std::getline(lines, line) && line != "study:") {
    if (line.rfind("identity = ", 0) == 0)
      m.identity = line.substr(11);
    else if (line.rfind("study_file = ", 0) == 0)
      m.study_file = line.substr(13);
    else if (line.rfind("set = ", 0) == 0)
      m.sets.push_back(line.substr(6));
  }
  std::string study;
  while (std::getline(lines, line) && line != "end of study") study += line + "\n";
  m.study_text = study;
  return m;
}

void write_manifest(const std::string& directory, const CheckpointManifest& m) {
  const std::string path = (fs::path(directory) / kManifestName).string();
  const std::string tmp = path + ".tmp";
  const std::string body = body_of(m);
  io::register_temp(tmp);
  errno = 0;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << body << "checksum = " << io::hex16(io::fnv1a64(body)) << "\n";
    out.close();
    if (!out) {
      const int err = errno ? errno : EIO;
      std::remove(tmp.c_str());
      io::unregister_temp(tmp);
      throw cannot_create("cannot write checkpoint manifest " + tmp + ": " +
                          (err == ENOSPC ? "no space left on device" : std::string(std::strerror(err))));
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  io::unregister_temp(tmp);
  if (ec) {
    std::remove(tmp.c_str());
    throw cannot_create("cannot rename checkpoint manifest " + tmp + ": " + ec.message());
  }
}

CheckpointLock::CheckpointLock(const std::string& directory)
    : directory_(directory), path_((fs::path(directory) / kLockName).string()) {
  // Another run may remove the lock file (and the directory) when it finishes between our open and
  // our flock: then the lock we hold is on a file nobody else sees, so try again.
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (::mkdir(directory_.c_str(), 0777) != 0 && errno != EEXIST)
      throw cannot_create("cannot create checkpoint directory " + directory_ + ": " + std::strerror(errno));
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) {
      if (errno == ENOENT) continue;
      throw cannot_create("cannot open checkpoint lock " + path_ + ": " + std::strerror(errno));
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      char pid[32] = {};
      [[maybe_unused]] const auto n = ::pread(fd_, pid, sizeof pid - 1, 0);
      ::close(fd_);
      fd_ = -1;
      std::string who = pid;
      while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
      throw cannot_create("another rollspec run" + (who.empty() ? std::string() : " (pid " + who + ")") +
                          " is using the checkpoint " + directory_ +
                          " of the same --out; wait for it to finish, or choose another --out");
    }
    struct stat a {
    }, b{};
    if (::fstat(fd_, &a) == 0 && ::stat(path_.c_str(), &b) == 0 && a.st_ino == b.st_ino && a.st_dev == b.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd_, 0) == 0) {
        [[maybe_unused]] const auto n = ::pwrite(fd_, pid.data(), pid.size(), 0);
      }
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
  throw cannot_create("cannot lock the checkpoint " + directory_ + ": it keeps being removed by another run");
}

CheckpointLock::~CheckpointLock() {
  if (fd_ < 0) return;
  // A run that failed before its first chunk leaves no checkpoint behind.
  bool only_bookkeeping = true;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory_, ec)) {
    const std::string name = entry.path().filename().string();
    if (name != kLockName && name != kManifestName) only_bookkeeping = false;
  }
  if (!ec && only_bookkeeping) {
    ::unlink((fs::path(directory_) / kManifestName).c_str());
    remove();
    return;
  }
  ::close(fd_);
}

void CheckpointLock::remove() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());
  ::rmdir(directory_.c_str());  // only if empty: the user's own files keep it
  ::close(fd_);
  fd_ = -1;
}

}  // namespace rollspec::ensemble
