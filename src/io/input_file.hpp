#pragma once
// Inputs must be regular files: a FIFO blocks a reader forever, /dev/zero never ends.
#include <sys/types.h>

#include <string>

namespace rollspec::io {

// "a directory", "a FIFO (named pipe)", "a character device", ... for messages.
const char* file_kind(mode_t mode);

// Refuses (exit 66) an input that exists but is neither a regular file nor a directory (FIFO,
// device, socket), naming `what` and what it is. A missing file or a directory is left to the
// caller's own message.
void require_regular_input(const std::string& path, const std::string& what);

}  // namespace rollspec::io
