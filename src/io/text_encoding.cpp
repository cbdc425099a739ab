#include "src/io/text_encoding.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "src/error.hpp"

namespace rollspec::io {

namespace {
void put_utf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// Text whose every other byte is NUL, in the first bytes: UTF-16 without its byte-order mark.
bool looks_like_bare_utf16(const std::string& head) {
  if (head.size() < 8) return false;
  std::size_t even = 0, odd = 0;
  for (std::size_t i = 0; i < head.size(); ++i) (i % 2 ? odd : even) += head[i] == '\0';
  const std::size_t half = head.size() / 2;
  return (odd * 10 >= half * 9 && even == 0) || (even * 10 >= half * 9 && odd == 0);
}
}  // namespace

std::string utf16_to_utf8(const std::string& bytes, bool big_endian) {
  std::string out;
  out.reserve(bytes.size() / 2);
  const auto unit = [&](std::size_t i) {
    const auto a = static_cast<unsigned char>(bytes[i]), b = static_cast<unsigned char>(bytes[i + 1]);
    return big_endian ? (static_cast<unsigned long>(a) << 8 | b) : (static_cast<unsigned long>(b) << 8 | a);
  };
  for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
    const unsigned long u = unit(i);
    if (u >= 0xD800 && u < 0xDC00 && i + 3 < bytes.size()) {
      const unsigned long low = unit(i + 2);
      if (low >= 0xDC00 && low < 0xE000) {
        put_utf8(out, 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00));
        i += 2;
        continue;
      }
    }
    put_utf8(out, u >= 0xD800 && u < 0xE000 ? 0xFFFD : u);
  }
  return out;
}

std::unique_ptr<std::istream> open_text(const std::string& path, std::string& encoding) {
  errno = 0;
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file)
    throw missing_input("cannot open '" + path + "'" + (errno ? std::string(": ") + std::strerror(errno) : ""));
  char buf[64] = {};
  file->read(buf, sizeof buf);
  const std::string head(buf, static_cast<std::size_t>(file->gcount()));
  file->clear();
  file->seekg(0);
  encoding.clear();
  const std::string resave = "; allowed: UTF-8 text (re-save the file as UTF-8, or as UTF-16 with a byte-order mark)";
  if (head.compare(0, 4, std::string("\xFF\xFE\0\0", 4)) == 0 ||
      head.compare(0, 4, std::string("\0\0\xFE\xFF", 4)) == 0)
    throw data_error(path + ": UTF-32 text" + resave);
  const bool le = head.compare(0, 2, "\xFF\xFE") == 0, be = head.compare(0, 2, "\xFE\xFF") == 0;
  if (!le && !be) {
    if (looks_like_bare_utf16(head)) throw data_error(path + ": UTF-16 text without a byte-order mark" + resave);
    return file;
  }
  encoding = le ? "UTF-16LE" : "UTF-16BE";
  const std::string bytes((std::istreambuf_iterator<char>(*file)), std::istreambuf_iterator<char>());
  if (bytes.size() % 2 != 0)
    throw data_error(path + ": " + encoding +
                     " text (byte-order mark) of an odd number of bytes: cut short or not UTF-16" + resave);
  return std::make_unique<std::istringstream>(utf16_to_utf8(bytes.substr(2), be));
}

}  // namespace rollspec::io
