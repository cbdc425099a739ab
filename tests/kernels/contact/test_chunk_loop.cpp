// for_each_chunk (kernels/contact/chunk_loop.hpp): every chunk once, on any team size, and an
// exception thrown in a chunk carried out of the parallel region.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include "kernels/contact/chunk_loop.hpp"

using rollspec::contact::detail::for_each_chunk;

TEST_CASE("for_each_chunk: every chunk once; an exception in a chunk is rethrown after the loop") {
  for (const int threads : {0, 1, 2, 3}) {
    CAPTURE(threads);
    // One entry per chunk: no two threads write the same one (no doctest assertion in the region).
    std::vector<int> seen(7, 0), thread_of(7, -1);
    for_each_chunk(seen.size(), threads, [&](std::size_t c, int thread) {
      ++seen[c];
      thread_of[c] = thread;
    });
    for (std::size_t c = 0; c < seen.size(); ++c) {
      CHECK(seen[c] == 1);
      CHECK(thread_of[c] >= 0);
    }
    CHECK_THROWS_AS(for_each_chunk(5, threads,
                                   [](std::size_t c, int) {
                                     if (c == 3) throw std::invalid_argument("chunk 3");
                                   }),
                    std::invalid_argument);
  }
  int calls = 0;
  for_each_chunk(0, 2, [&](std::size_t, int) { ++calls; });
  CHECK(calls == 0);
}
