#include "src/io/input_file.hpp"

#include <sys/stat.h>

#include "src/error.hpp"

namespace rollspec::io {

const char* file_kind(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISREG(m)) return "a regular file";
  return "not a regular file";
}

void require_regular_input(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  if (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)) return;
  throw missing_input("cannot read " + what + " '" + path + "': it is " + file_kind(st.st_mode) +
                      "; allowed: a regular file");
}

}  // namespace rollspec::io
