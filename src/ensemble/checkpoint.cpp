#include "src/ensemble/checkpoint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/temp_files.hpp"
#include "src/io/number_text.hpp"

namespace fs = std::filesystem;

namespace rollspec::ensemble {

namespace {
constexpr char kMagic[8] = {'R', 'S', 'C', 'H', 'U', 'N', 'K', '1'};

std::string chunk_name(std::uint64_t lo, std::uint64_t hi) {
  return io::formatted("chunk_%012llu_%012llu.bin", static_cast<unsigned long long>(lo),
                       static_cast<unsigned long long>(hi));
}
}  // namespace

CheckpointStore::CheckpointStore(std::string directory, std::uint64_t study_hash)
    : directory_(std::move(directory)), hash_(study_hash) {}

void CheckpointStore::write(const ChunkSums& c) const {
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec) throw cannot_create("cannot create checkpoint directory " + directory_ + ": " + ec.message());
  std::vector<char> buf(sizeof kMagic + 4 * sizeof(std::uint64_t) + c.values.size() * sizeof(double));
  char* p = buf.data();
  const std::uint64_t n = c.values.size();
  std::memcpy(p, kMagic, sizeof kMagic), p += sizeof kMagic;
  for (std::uint64_t v : {hash_, c.lo, c.hi, n}) std::memcpy(p, &v, sizeof v), p += sizeof v;
  std::memcpy(p, c.values.data(), c.values.size() * sizeof(double));
  const std::uint64_t sum = io::fnv1a64(buf.data(), buf.size());
  const std::string final_name = (fs::path(directory_) / chunk_name(c.lo, c.hi)).string();
  const std::string tmp = final_name + ".tmp";
  io::register_temp(tmp);
  auto fail = [&](const std::string& what, int err) {
    std::remove(tmp.c_str());
    io::unregister_temp(tmp);
    return cannot_create("cannot " + what + " checkpoint " + tmp + ": " +
                         (err == ENOSPC ? "no space left on device; free some space and rerun with --resume"
                                        : std::string(std::strerror(err))));
  };
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    out.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    out.close();  // the last buffered bytes are written here: a full disk shows up now
    if (!out) throw fail("write", errno ? errno : EIO);
  }
  fs::rename(tmp, final_name, ec);
  if (ec) throw fail("rename", ec.value());
  io::unregister_temp(tmp);
}

namespace {
// The first `bytes` of a file by one read (an ifstream would read a whole buffer: 8 KiB per chunk
// header, which a scan of 10^5 chunks pays many times over); fewer if the file is shorter.
std::vector<char> read_prefix(const std::string& path, std::size_t bytes) {
  std::vector<char> buf(bytes);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  std::size_t done = 0;
  while (fd >= 0 && done < bytes) {
    const ssize_t n = ::read(fd, buf.data() + done, bytes - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  if (fd >= 0) ::close(fd);
  buf.resize(done);
  return buf;
}

std::size_t chunk_file_size(std::size_t n_values) {
  return sizeof kMagic + 4 * sizeof(std::uint64_t) + n_values * sizeof(double) + sizeof(std::uint64_t);
}

// Reads the first `bytes` of one chunk file after checking its kind and size (a FIFO would block the
// read, a huge file would be read whole), then its magic and study hash; returns them.
std::vector<char> read_chunk_bytes(const std::string& where, std::size_t n_values, std::uint64_t hash,
                                   std::size_t bytes) {
  const std::size_t expect = chunk_file_size(n_values);
  struct stat st {};
  if (::lstat(where.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    throw data_error(where + ": not a regular file; a checkpoint chunk is a file rollspec wrote");
  if (static_cast<std::size_t>(st.st_size) != expect)
    throw data_error(where + ": damaged checkpoint (size " + std::to_string(st.st_size) + " bytes, expected " +
                     std::to_string(expect) + "); start over with --restart");
  const std::vector<char> buf = read_prefix(where, bytes);
  if (buf.size() != bytes || std::memcmp(buf.data(), kMagic, sizeof kMagic) != 0)
    throw data_error(where + ": damaged checkpoint (size or magic); start over with --restart");
  std::uint64_t h = 0;
  std::memcpy(&h, buf.data() + sizeof kMagic, sizeof h);
  if (h != hash)
    throw data_error(where +
                     ": checkpoint belongs to a different study (input hash differs); start over with --restart");
  return buf;
}

// The chunk bounds [lo, hi) a header holds.
std::pair<std::uint64_t, std::uint64_t> header_bounds(const std::vector<char>& buf) {
  std::uint64_t h[4];
  std::memcpy(h, buf.data() + sizeof kMagic, sizeof h);
  return {h[1], h[2]};
}

// Reads and checks one chunk file whole: kind, size, magic, study hash, checksum.
ChunkSums read_chunk_file(const std::string& where, std::size_t n_values, std::uint64_t hash) {
  const std::vector<char> buf = read_chunk_bytes(where, n_values, hash, chunk_file_size(n_values));
  std::uint64_t stored = 0;
  std::memcpy(&stored, buf.data() + buf.size() - sizeof stored, sizeof stored);
  if (stored != io::fnv1a64(buf.data(), buf.size() - sizeof stored))
    throw DamagedChunk(where + ": damaged checkpoint (checksum)");
  ChunkSums c;
  std::tie(c.lo, c.hi) = header_bounds(buf);
  c.values.resize(n_values);
  std::memcpy(c.values.data(), buf.data() + sizeof kMagic + 4 * sizeof(std::uint64_t), n_values * sizeof(double));
  return c;
}
}  // namespace

void CheckpointStore::scan(std::size_t n_values, const std::function<void(std::uint64_t, std::uint64_t)>& each) const {
  std::error_code ec;
  if (!fs::is_directory(directory_, ec)) return;
  const std::size_t header = sizeof kMagic + 4 * sizeof(std::uint64_t);
  for (const auto& entry : fs::directory_iterator(directory_)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("chunk_", 0) != 0 || entry.path().extension() != ".bin") continue;  // skips *.tmp leftovers
    const auto [lo, hi] = header_bounds(read_chunk_bytes(entry.path().string(), n_values, hash_, header));
    // The name is what read() opens: a file renamed by hand is damaged, not another chunk.
    if (name != chunk_name(lo, hi))
      throw data_error(entry.path().string() + ": damaged checkpoint (its name does not match the chunk it holds, " +
                       chunk_name(lo, hi) + "); start over with --restart");
    each(lo, hi);
  }
}

bool CheckpointStore::has(std::uint64_t lo, std::uint64_t hi) const {
  struct stat st {};
  return ::lstat((fs::path(directory_) / chunk_name(lo, hi)).c_str(), &st) == 0;
}

ChunkSums CheckpointStore::read(std::uint64_t lo, std::uint64_t hi, std::size_t n_values) const {
  const std::string where = (fs::path(directory_) / chunk_name(lo, hi)).string();
  ChunkSums c = read_chunk_file(where, n_values, hash_);
  if (c.lo != lo || c.hi != hi)
    throw data_error(where + ": damaged checkpoint (chunk bounds); start over with --restart");
  return c;
}

bool is_checkpoint_file_name(const std::string& name) {
  if (name == kManifestName || name == kLockName || name == std::string(kManifestName) + ".tmp") return true;
  if (name.rfind("chunk_", 0) != 0) return false;
  const auto ends_with = [&](const std::string& suffix) {
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".bin") || ends_with(".bin.tmp");
}

bool is_chunk_file(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  const std::vector<char> magic = read_prefix(path, sizeof kMagic);
  return magic.size() == sizeof kMagic && std::memcmp(magic.data(), kMagic, sizeof kMagic) == 0;
}

std::vector<std::string> CheckpointStore::foreign_entries() const {
  std::vector<std::string> out;
  std::error_code ec;
  fs::directory_iterator it(directory_, ec);
  if (ec) return out;
  for (const auto& entry : it) {
    const std::string name = entry.path().filename().string();
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) != 0 && errno == ENOENT) continue;  // renamed meanwhile by a running writer
    const bool regular = S_ISREG(st.st_mode);
    const bool ours =
        regular && is_checkpoint_file_name(name) &&
        (name.size() < 4 || name.compare(name.size() - 4, 4, ".bin") != 0 || is_chunk_file(entry.path().string()));
    if (!ours) out.push_back(name);
  }
  return out;
}

std::size_t CheckpointStore::chunk_count() const {
  std::size_t n = 0;
  std::error_code ec;
  fs::directory_iterator it(directory_, ec);
  if (ec) return 0;
  for (const auto& entry : it) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("chunk_", 0) == 0 && entry.path().extension() == ".bin" && is_chunk_file(entry.path().string())) ++n;
  }
  return n;
}

void CheckpointStore::clear(bool keep_lock) const {
  std::error_code ec;
  fs::directory_iterator it(directory_, ec);
  if (ec) return;
  std::vector<fs::path> ours;
  for (const auto& entry : it) {
    const std::string name = entry.path().filename().string();
    if (keep_lock && name == kLockName) continue;
    if (!is_checkpoint_file_name(name)) continue;  // the user's own files stay
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    if (entry.path().extension() == ".bin" && !is_chunk_file(entry.path().string())) continue;
    ours.push_back(entry.path());
  }
  // The manifest goes last: a directory with chunks but no manifest is never left behind.
  std::sort(ours.begin(), ours.end(), [](const fs::path& a, const fs::path& b) {
    return (a.filename() == kManifestName) < (b.filename() == kManifestName);
  });
  for (const auto& p : ours) fs::remove(p, ec);
  if (!keep_lock) fs::remove(directory_, ec);  // only if now empty
}

}  // namespace rollspec::ensemble
