#pragma once
// SIGINT / SIGTERM ask a running ensemble to stop: workers finish nothing new, completed
// chunks are already on disk, and the command exits 130 so `--resume` can finish the job.
#include <atomic>

namespace rollspec::ensemble {

void install_stop_handlers();
bool stop_requested();
void request_stop();  // for tests

}  // namespace rollspec::ensemble
