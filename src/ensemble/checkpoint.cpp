#include "src/ensemble/checkpoint.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/error.hpp"

namespace fs = std::filesystem;

namespace rollspec::ensemble {

namespace {
constexpr char kMagic[8] = {'R', 'S', 'C', 'H', 'U', 'N', 'K', '1'};

std::string chunk_name(std::uint64_t lo, std::uint64_t hi) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "chunk_%012llu_%012llu.bin", static_cast<unsigned long long>(lo),
                static_cast<unsigned long long>(hi));
  return buf;
}
}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t n, std::uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t fnv1a64(const std::string& s) { return fnv1a64(s.data(), s.size()); }

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
  const std::uint64_t sum = fnv1a64(buf.data(), buf.size());
  const std::string final_name = (fs::path(directory_) / chunk_name(c.lo, c.hi)).string();
  const std::string tmp = final_name + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    out.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    if (!out) throw cannot_create("cannot write checkpoint " + tmp);
  }
  fs::rename(tmp, final_name, ec);
  if (ec) throw cannot_create("cannot rename checkpoint " + tmp + ": " + ec.message());
}

std::map<std::uint64_t, ChunkSums> CheckpointStore::load(std::size_t n_values) const {
  std::map<std::uint64_t, ChunkSums> out;
  std::error_code ec;
  if (!fs::is_directory(directory_, ec)) return out;
  for (const auto& entry : fs::directory_iterator(directory_)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("chunk_", 0) != 0 || entry.path().extension() != ".bin") continue;  // skips *.tmp leftovers
    std::ifstream in(entry.path(), std::ios::binary);
    std::vector<char> buf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t expect = sizeof kMagic + 4 * sizeof(std::uint64_t) + n_values * sizeof(double) + sizeof(std::uint64_t);
    const std::string where = entry.path().string();
    if (buf.size() != expect || std::memcmp(buf.data(), kMagic, sizeof kMagic) != 0)
      throw data_error(where + ": damaged checkpoint (size or magic); remove the checkpoint directory or run without --resume");
    std::uint64_t stored = 0;
    std::memcpy(&stored, buf.data() + buf.size() - sizeof stored, sizeof stored);
    if (stored != fnv1a64(buf.data(), buf.size() - sizeof stored))
      throw data_error(where + ": damaged checkpoint (checksum); remove it or run without --resume");
    std::uint64_t h[4];
    std::memcpy(h, buf.data() + sizeof kMagic, sizeof h);
    if (h[0] != hash_)
      throw data_error(where + ": checkpoint belongs to a different study (input hash differs); run without --resume");
    ChunkSums c;
    c.lo = h[1];
    c.hi = h[2];
    c.values.resize(n_values);
    std::memcpy(c.values.data(), buf.data() + sizeof kMagic + sizeof h, n_values * sizeof(double));
    out[c.lo] = std::move(c);
  }
  return out;
}

void CheckpointStore::clear() const {
  std::error_code ec;
  fs::remove_all(directory_, ec);
}

}  // namespace rollspec::ensemble
