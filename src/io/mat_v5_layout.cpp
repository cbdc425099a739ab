#include "src/io/mat_v5_layout.hpp"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "src/error.hpp"

namespace rollspec::io {

namespace {

using Bytes = std::vector<unsigned char>;

// MAT-File Format (MathWorks, 2019), "Data Element Tag": data types and their sizes in bytes.
constexpr std::uint32_t kMiMatrix = 14, kMiCompressed = 15;
std::size_t type_size(std::uint32_t type) {
  switch (type) {
    case 1:
    case 2:
    case 16:
      return 1;  // miINT8, miUINT8, miUTF8
    case 3:
    case 4:
    case 17:
      return 2;  // miINT16, miUINT16, miUTF16
    case 5:
    case 6:
    case 7:
    case 18:
      return 4;  // miINT32, miUINT32, miSINGLE, miUTF32
    case 9:
    case 12:
    case 13:
      return 8;  // miDOUBLE, miINT64, miUINT64
    default:
      return 0;
  }
}

struct Reader {
  const Bytes& b;
  bool swap;
  const std::string& path;
  std::uint32_t u32(std::size_t at) const {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return swap ? __builtin_bswap32(v) : v;
  }
  [[noreturn]] void damaged(const std::string& what) const {
    throw data_error(path + ": " + what + "; the .mat file is cut short or damaged; allowed: an undamaged .mat file");
  }
};

struct Element {
  std::uint32_t type = 0;
  std::size_t size = 0;  // bytes of data
  std::size_t data = 0;  // offset of the data
  std::size_t next = 0;  // offset of the next element (8-byte aligned, or packed for small elements)
};

Element element_at(const Reader& r, std::size_t at, std::size_t end) {
  if (at + 8 > end)
    r.damaged("a data element's tag at byte " + std::to_string(at) + " runs past the end of its container");
  Element e;
  const std::uint32_t first = r.u32(at);
  if (first >> 16) {  // small data element: size in the upper half, data in the tag's second word
    e.type = first & 0xffffu;
    e.size = first >> 16;
    e.data = at + 4;
    e.next = at + 8;
    if (e.size > 4)
      r.damaged("a small data element at byte " + std::to_string(at) + " claims " + std::to_string(e.size) + " bytes");
    return e;
  }
  e.type = first;
  e.size = r.u32(at + 4);
  e.data = at + 8;
  if (e.size > end - e.data)
    r.damaged("a data element at byte " + std::to_string(at) + " claims " + std::to_string(e.size) + " bytes, " +
              std::to_string(end - e.data) + " are there");
  e.next = e.type == kMiCompressed ? e.data + e.size : e.data + ((e.size + 7) / 8) * 8;
  if (e.next > end) e.next = end;  // the last element's padding may be missing
  return e;
}

// miMATRIX contents: array flags, dimensions, name, then (numeric classes) real and imaginary parts.
void check_matrix(const Reader& r, const Element& m) {
  const std::size_t end = m.data + m.size;
  const Element flags = element_at(r, m.data, end);
  if (flags.size < 8) r.damaged("a variable's array flags are " + std::to_string(flags.size) + " bytes");
  const std::uint32_t word = r.u32(flags.data);
  const std::uint32_t cls = word & 0xffu;
  const bool complex = (word & 0x0800u) != 0;
  if (cls < 6 || cls > 15) return;  // not numeric (cell, struct, char, sparse, ...): the reader lists it as skipped
  const Element dims = element_at(r, flags.next, end);
  std::size_t numel = 1;
  std::string shape;
  for (std::size_t i = 0; i + 4 <= dims.size; i += 4) {
    const std::uint32_t d = r.u32(dims.data + i);
    numel *= d;
    shape += (shape.empty() ? "" : "x") + std::to_string(d);
  }
  const Element name = element_at(r, dims.next, end);
  const std::string var(reinterpret_cast<const char*>(r.b.data() + name.data), name.size);
  std::size_t at = name.next;
  for (int part = 0; part < (complex ? 2 : 1); ++part) {
    const Element d = element_at(r, at, end);
    const std::size_t size = type_size(d.type);
    if (size == 0) r.damaged("variable '" + var + "' stores data of unknown type " + std::to_string(d.type));
    if (d.size != numel * size)
      throw data_error(r.path + ": variable '" + var + "' declares " + shape + " = " + std::to_string(numel) +
                       " elements but stores " + std::to_string(d.size / size) +
                       (d.size % size ? " and a fraction" : "") +
                       "; the .mat file is damaged; allowed: dimensions that match the stored data");
    at = d.next;
  }
}

Bytes inflate_element(const Reader& r, const Element& e) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) throw data_error(r.path + ": cannot start zlib to check a compressed variable");
  z.next_in = const_cast<unsigned char*>(r.b.data() + e.data);
  z.avail_in = static_cast<uInt>(e.size);
  Bytes out;
  int rc = Z_OK;
  unsigned char buf[1 << 15];
  while (rc == Z_OK) {
    z.next_out = buf;
    z.avail_out = sizeof buf;
    rc = inflate(&z, Z_NO_FLUSH);
    out.insert(out.end(), buf, buf + (sizeof buf - z.avail_out));
    if (rc == Z_BUF_ERROR && z.avail_in == 0) break;  // input ends before the stream does
  }
  inflateEnd(&z);
  if (rc != Z_STREAM_END)
    r.damaged("a compressed variable at byte " + std::to_string(e.data - 8) + " does not decompress (zlib " +
              std::to_string(rc) + ")");
  return out;
}

}  // namespace

void check_mat_v5_layout(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const Bytes b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (b.size() < 128) return;
  const std::uint16_t version = static_cast<std::uint16_t>(b[124] | (b[125] << 8));
  const bool little = b[126] == 'I' && b[127] == 'M', big = b[126] == 'M' && b[127] == 'I';
  if (!(little || big) || (version != 0x0100 && version != 0x0001)) return;  // not MAT v5
  const Reader r{b, big, path};
  for (std::size_t at = 128; at < b.size();) {
    const Element e = element_at(r, at, b.size());
    if (e.type == kMiMatrix) {
      check_matrix(r, e);
    } else if (e.type == kMiCompressed) {
      const Bytes inner = inflate_element(r, e);
      const Reader ir{inner, big, path};
      const Element m = element_at(ir, 0, inner.size());
      if (m.type == kMiMatrix) check_matrix(ir, m);
    }
    at = e.next;
  }
}

}  // namespace rollspec::io
