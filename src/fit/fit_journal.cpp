#include "src/fit/fit_journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/input_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::fit {

namespace {

constexpr const char* kHeader = "# rollspec fit journal ";

// The key's content hash, fed piece by piece. It starts from 1469598103934665603, a digit short of
// FNV's offset basis since the journal's first version: kept, so existing journals stay valid.
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const std::string& s) {
    static const unsigned char separator = 0xff;  // ("ab", "c") differs from ("a", "bc")
    h = io::fnv1a64(&separator, 1, io::fnv1a64(s.data(), s.size(), h));
  }
  void add(double v) { add(io::exact_text(v)); }
  void add_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    add(s.str());
  }
};

}  // namespace

std::uint64_t fit_journal_key(const FitInputs& in, const std::string& column) {
  Fnv f;
  f.add(io::code_identity());
  f.add_file(in.study);
  for (const auto& s : in.sets) f.add("set " + s);
  for (const auto& v : in.vary) f.add(v.key), f.add(v.lo), f.add(v.hi), f.add(v.log ? "log" : "linear");
  f.add("sensor " + in.sensor.name), f.add(in.sensor.position ? *in.sensor.position : NAN);
  f.add("column " + column), f.add(in.fmin), f.add(in.fmax);
  for (const auto& p : in.points) f.add_file(p.path), f.add("at " + p.at), f.add(p.records);
  f.add(in.same_surface ? "same surface" : "new surface");
  return f.h;
}

namespace {

constexpr std::uintmax_t kLargestJournal = 64u << 20;  // a line is ~80 bytes: far more than any fit evaluates

// The journal's bytes, or nullopt if there is none; refused at once if it is not a regular file.
std::optional<std::string> read_journal(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return std::nullopt;
    throw cannot_create("--journal " + path + ": " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode))
    throw cannot_create("--journal " + path + " is " + io::file_kind(st.st_mode) +
                        "; allowed: a new file or the journal of this fit (a regular file)");
  if (static_cast<std::uintmax_t>(st.st_size) > kLargestJournal)
    throw cannot_create("--journal " + path + ": " + std::to_string(st.st_size >> 20) +
                        " MiB, larger than any fit journal; allowed: a new file or the journal of this fit");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw cannot_create("--journal " + path + ": " + std::strerror(errno));
  std::string text;
  char buf[65536];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 || text.size() + static_cast<std::size_t>(n) > kLargestJournal) {
      ::close(fd);
      throw cannot_create("--journal " + path + ": cannot read it whole");
    }
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

}  // namespace

FitJournal::FitJournal(std::string path, std::uint64_t key) : path_(std::move(path)), key_(key) {
  const auto text = read_journal(path_);
  if (!text) {  // a new journal: its folder must take it, before the first evaluation runs
    const std::filesystem::path dir = std::filesystem::absolute(path_).parent_path();
    if (!std::filesystem::is_directory(dir) || ::access(dir.c_str(), W_OK | X_OK) != 0)
      throw cannot_create("--journal " + path_ + ": cannot create it in " + dir.string() +
                          " (no such folder, or not writable)");
    return;
  }
  const std::string expected = kHeader + io::hex16(key_);
  const std::size_t end = text->find('\n');
  const std::string first = text->substr(0, end);
  if (end == std::string::npos || first.rfind(kHeader, 0) != 0)
    throw cannot_create("--journal " + path_ +
                        ": not a rollspec fit journal; allowed: a new file or the journal of "
                        "this fit (remove it or choose another path)");
  if (first != expected)
    throw cannot_create("--journal " + path_ +
                        ": the journal of another fit (its study, measurements, options or build differ); allowed: "
                        "the journal of this fit, or a new file (remove it or choose another path)");
  whole_ = true;
  std::size_t at = end + 1;
  for (int number = 2; at < text->size(); ++number) {
    const std::size_t eol = text->find('\n', at);
    if (eol == std::string::npos) {  // torn: its write did not finish (a crash, a full disk)
      whole_ = false;
      break;
    }
    const std::string line = text->substr(at, eol - at);
    at = eol + 1;
    const auto bar = line.find(';');
    std::vector<double> point, values;
    bool ok = bar != std::string::npos;
    for (int half = 0; half < 2 && ok; ++half) {
      std::istringstream s(half == 0 ? line.substr(0, bar) : line.substr(bar + 1));
      auto& row = half == 0 ? point : values;
      for (std::string word; s >> word;) {
        char* stop = nullptr;
        row.push_back(std::strtod(word.c_str(), &stop));
        if (*stop != '\0' || !std::isfinite(row.back())) ok = false;
      }
      ok = ok && !row.empty();
    }
    if (!ok)
      throw data_error(path_ + ":" + std::to_string(number) +
                       ": not a line of an evaluation's key and values (numbers, then ';', then numbers)");
    order_.emplace_back(point, values);
    entries_.emplace(point, values);
  }
}

bool FitJournal::find(const std::vector<double>& key, std::vector<double>& values) const {
  const auto hit = entries_.find(key);
  if (hit == entries_.end()) return false;
  values = hit->second;
  return true;
}

namespace {
// "key ; values": the parameter vector (and a replicate's index), then what the fit read from it.
std::string journal_line(const std::vector<double>& x, const std::vector<double>& v) {
  std::string line;
  for (const double c : x) line += io::formatted("%.17g ", c);
  line += ";";
  for (const double c : v) line += io::formatted(" %.17g", c);
  return line + "\n";
}

void write_all(int fd, const std::string& bytes, const std::string& what) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw cannot_create("--journal " + what + ": " + std::strerror(n < 0 ? errno : EIO));
    done += static_cast<std::size_t>(n);
  }
}
}  // namespace

// The whole journal through a temporary renamed onto it: the old file stays whole if this fails.
void FitJournal::rewrite() {
  std::string bytes = kHeader + io::hex16(key_) + "\n";
  for (const auto& [x, v] : order_) bytes += journal_line(x, v);
  const std::string temp = io::temp_name(path_);
  io::register_temp(temp);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    io::unregister_temp(temp);
    throw cannot_create("--journal " + path_ + ": cannot write " + temp + ": " + std::strerror(errno));
  }
  try {
    write_all(fd, bytes, path_);
    if (::fsync(fd) != 0) throw cannot_create("--journal " + path_ + ": " + std::strerror(errno));
  } catch (...) {
    ::close(fd);
    std::remove(temp.c_str());
    io::unregister_temp(temp);
    throw;
  }
  ::close(fd);
  const ensemble::CriticalSection keep;  // an interrupt waits for the rename
  std::error_code ec;
  std::filesystem::rename(temp, path_, ec);
  if (ec) std::remove(temp.c_str());
  io::unregister_temp(temp);
  if (ec) throw cannot_create("--journal " + path_ + ": cannot rename " + temp + " onto it: " + ec.message());
  whole_ = true;
}

// One evaluation, one write: a crash leaves at most this line torn, which the next reader discards.
void FitJournal::append(const std::string& line) {
  const int fd = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_NONBLOCK | O_CLOEXEC);
  struct stat st {};
  if (fd < 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    if (fd >= 0) ::close(fd);
    throw cannot_create("--journal " + path_ + ": no longer the journal this fit wrote (moved or replaced)");
  }
  const ensemble::CriticalSection keep;  // an interrupt waits for the line
  try {
    write_all(fd, line, path_);
    if (::fsync(fd) != 0) throw cannot_create("--journal " + path_ + ": " + std::strerror(errno));
  } catch (...) {
    ::close(fd);
    whole_ = false;  // the line may be torn: the next record rewrites the file
    throw;
  }
  ::close(fd);
}

void FitJournal::record(const std::vector<double>& key, const std::vector<double>& values) {
  order_.emplace_back(key, values);
  entries_.emplace(key, values);
  if (whole_)
    append(journal_line(key, values));
  else
    rewrite();
}

}  // namespace rollspec::fit
