#pragma once
// The fuzz harnesses' input file: the readers they fuzz take a path, so each input is written to one temporary file
// per fuzzing process, /tmp/rollspec-fuzz-<name>-<pid><suffix>, removed when the process exits.
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <fstream>
#include <string>

namespace rollspec::fuzz {

struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& suffix)
      : path("/tmp/rollspec-fuzz-" + name + "-" + std::to_string(::getpid()) + suffix) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() { std::remove(path.c_str()); }

  // Replaces the file's content by `size` bytes from `data`.
  void write(const char* data, std::size_t size) const {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(data, static_cast<std::streamsize>(size));
  }
};

}  // namespace rollspec::fuzz
