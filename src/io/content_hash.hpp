#pragma once
// SHA-256 of a file's or a text's bytes (OpenSSL's libcrypto), as lower-case hex: what `sha256sum`
// prints, so a user can check a recorded hash with standard tools. Records which file a PSD was
// computed from, and that a CSV is the one rollspec wrote (psd_csv.hpp).
#include <string>

namespace rollspec::io {

std::string sha256_hex(const std::string& bytes);

// Throws missing_input if the file cannot be opened, data_error if it cannot be read to its end.
std::string sha256_file(const std::string& path);

}  // namespace rollspec::io
