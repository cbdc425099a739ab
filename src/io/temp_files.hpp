#pragma once
// Temporary files rollspec writes beside an output ("<final>.tmp-<pid>") before renaming them onto
// it. Each writer registers its temporary file while it exists, so an interrupt in any phase can
// remove them (stop_signal.cpp) and leave nothing partial behind; a kill -9 cannot, so the next
// write to the same output removes temporaries whose process is gone.
#include <string>

namespace rollspec::io {

// "<final>.tmp-<this pid>".
std::string temp_name(const std::string& final_path);

void register_temp(const std::string& path);
void unregister_temp(const std::string& path);
// A temporary directory (a fit's run files), removed with everything in it on an interrupt.
void register_temp_dir(const std::string& path);
void unregister_temp_dir(const std::string& path);
// Removes every registered temporary file. Async-signal-unsafe: called by the stop watchdog thread.
void remove_registered_temps();

// Removes "<final>.tmp-<pid>" files beside final_path whose process no longer exists (a run killed
// during its final write). Files of a live process, and anything that is not a regular file, are
// left alone. Returns the number removed.
int remove_stale_temps(const std::string& final_path);

}  // namespace rollspec::io
