#pragma once
// The stored layout of a MATLAB v5 .mat file, checked before matio reads it. matio allocates a
// numeric variable from its declared dimensions and reads as many bytes as the data element holds,
// so dimensions larger than the stored data leave the rest of the array uninitialised, and smaller
// ones cut the data silently. This walks the file's data elements (compressed ones through zlib)
// and refuses a numeric variable whose stored element count differs from its dimensions, or an
// element that claims more bytes than the file holds.
#include <string>

namespace rollspec::io {

// No-op for files that are not MAT v5 (v4 and v7.3 are checked by their readers). Throws
// data_error naming the file, the variable, its dimensions and the elements stored.
void check_mat_v5_layout(const std::string& path);

}  // namespace rollspec::io
