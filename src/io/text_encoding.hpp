#pragma once
// Text files in the encodings loggers and spreadsheets save: UTF-8 (with or without a byte-order mark,
// read as it is) and UTF-16 with a byte-order mark (little or big endian: Windows "Unicode text"),
// converted to UTF-8 here. UTF-16 without a byte-order mark and UTF-32 are refused in one line that
// names the fix: re-save as UTF-8.
#include <memory>
#include <istream>
#include <string>

namespace rollspec::io {

// The text of `path` as a stream of UTF-8: the file itself, or its UTF-16 converted. `encoding` is set
// to "" (UTF-8 or ASCII), "UTF-16LE" or "UTF-16BE". Throws data_error for UTF-16 without a
// byte-order mark, UTF-32 or a UTF-16 file of odd length; missing_input if it cannot be opened.
std::unique_ptr<std::istream> open_text(const std::string& path, std::string& encoding);

// UTF-16 code units (big or little endian bytes, no byte-order mark) to UTF-8; unpaired surrogates
// become U+FFFD.
std::string utf16_to_utf8(const std::string& bytes, bool big_endian);

}  // namespace rollspec::io
