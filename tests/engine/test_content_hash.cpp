// The cache keys' content hash (io/content_hash.hpp) against FNV-1a's published 64-bit test vectors
// (Fowler, Noll, Vo: "", "a", "foobar"): the values are stored on disk as table names, input hashes,
// checkpoint headers and journal keys, so they must never change.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "src/io/content_hash.hpp"

using namespace rollspec;

TEST_CASE("content hash: FNV-1a 64 test vectors, continued hashing, and its text") {
  CHECK(io::fnv1a64(std::string()) == 0xcbf29ce484222325ull);
  CHECK(io::fnv1a64(std::string("a")) == 0xaf63dc4c8601ec8cull);
  CHECK(io::fnv1a64(std::string("foobar")) == 0x85944171f73967e8ull);
  // Hashing in pieces, each continuing from the last, is hashing the whole (the tables' inputs and columns).
  CHECK(io::fnv1a64("bar", 3, io::fnv1a64("foo", 3)) == io::fnv1a64(std::string("foobar")));
  const std::vector<double> column = {1.0, -2.5};
  CHECK(io::fnv1a64(column.data(), 2 * sizeof(double)) ==
        io::fnv1a64(&column[1], sizeof(double), io::fnv1a64(&column[0], sizeof(double))));
  CHECK(io::hex16(0xaf63dc4c8601ec8cull) == "af63dc4c8601ec8c");
  CHECK(io::hex16(0x2a) == "000000000000002a");
}
