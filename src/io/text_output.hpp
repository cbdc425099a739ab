#pragma once
// Writes a small text file whole or not at all: into "<path>.tmp-<pid>" (registered, so an
// interrupt removes it), then renamed onto the path. Call check_output_target() first.
#include <string>

namespace rollspec::io {

// write_path: what check_output_target() returned; shown: the path as the user gave it (messages).
// Throws cannot_create (exit 73) naming the path and the system's reason.
void write_text_file(const std::string& write_path, const std::string& shown, const std::string& text);

}  // namespace rollspec::io
