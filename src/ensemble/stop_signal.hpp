#pragma once
// SIGINT, SIGTERM and SIGHUP stop every phase of every command within about a second, with exit 130:
//   - the ensemble loop sees stop_requested() between realisations and stops cleanly (completed
//     chunks are already checkpointed; `--resume` finishes the job);
//   - any other phase (table builds, single runs, texture synthesis, writing) is ended by a
//     watchdog thread once a short grace period has passed: it removes the registered temporary
//     files (io/temp_files.hpp) and exits 130. Completed tables and chunks were renamed into place
//     whole, so they are kept; nothing partial is.
// A CriticalSection (renaming a finished result, clearing its checkpoint) delays that exit until it
// ends, so a committed result never loses its bookkeeping half-way.
#include <atomic>

namespace rollspec::ensemble {

// Installs the handlers (first thing in main; idempotent).
void install_stop_handlers();
bool stop_requested();
// For a caller that runs the engine in-process (the Python module) and notices an interrupt itself:
// request_stop() stops the ensemble loop as a signal would (no watchdog, no exit: the run throws its
// exit-130 error), clear_stop() before the next run.
void request_stop();
void clear_stop();

class CriticalSection {
 public:
  CriticalSection();
  ~CriticalSection();
  CriticalSection(const CriticalSection&) = delete;
  CriticalSection& operator=(const CriticalSection&) = delete;
};

}  // namespace rollspec::ensemble
