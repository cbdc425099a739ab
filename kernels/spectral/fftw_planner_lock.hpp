#pragma once
// FFTW's planner is not thread-safe; every plan creation and destruction in rollspec takes
// this one lock. Executing a plan (new-array interface) needs no lock.
#include <mutex>

namespace rollspec::spectral {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace rollspec::spectral
