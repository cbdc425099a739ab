#pragma once
// The chunked OpenMP loop of the path kernels (blocked_force.cpp, equivalent_roughness.cpp): chunks
// of positions in parallel, each chunk's positions in order on one thread, exceptions carried out
// of the parallel region. Which thread runs a chunk never changes its bits (a solve depends on its
// inputs only). Internal to the kernel.
#include <omp.h>

#include <cstddef>
#include <exception>

namespace rollspec::contact::detail {

// body(c, thread) for every chunk c in [0, chunks), one chunk at a time per thread (dynamic, 1), on
// `threads` threads (≤ 0: the default team, omp_get_max_threads()); `thread` is omp_get_thread_num().
// The first exception a chunk threw is rethrown after the loop (none may leave the region).
template <class Body>
void for_each_chunk(std::size_t chunks, int threads, Body&& body) {
  const int team = threads > 0 ? threads : omp_get_max_threads();
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(team)
  for (std::ptrdiff_t c = 0; c < static_cast<std::ptrdiff_t>(chunks); ++c) {
    try {
      body(static_cast<std::size_t>(c), omp_get_thread_num());
    } catch (...) {
#pragma omp critical(rollspec_contact_chunk_error)
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace rollspec::contact::detail
