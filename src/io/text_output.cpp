#include "src/io/text_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::io {

void write_text_file(const std::string& write_path, const std::string& shown, const std::string& text) {
  const std::string tmp = temp_name(write_path);
  register_temp(tmp);
  const auto fail = [&](const std::string& what, int err) {
    std::remove(tmp.c_str());
    unregister_temp(tmp);
    return cannot_create(what + " (writing " + tmp + ": " +
                         (err == ENOSPC ? std::string("no space left on device") : std::string(std::strerror(err))) +
                         ")");
  };
  {
    errno = 0;
    std::ofstream o(tmp, std::ios::trunc | std::ios::binary);
    if (!o) throw fail("cannot create output file '" + shown + "'", errno ? errno : EIO);
    o << text;
    o.close();
    if (!o) throw fail("cannot write output file '" + shown + "'", errno ? errno : EIO);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, write_path, ec);
  if (ec) throw fail("cannot create output file '" + shown + "': " + ec.message(), ec.value());
  unregister_temp(tmp);
}

}  // namespace rollspec::io
