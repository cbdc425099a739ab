#pragma once
// Engine doctests that write files start from an empty directory of their own under the system's temporary
// directory: what an earlier run left there is removed first.
#include <filesystem>
#include <string>

namespace rollspec::test {

inline std::filesystem::path fresh_directory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace rollspec::test
