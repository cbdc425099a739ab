// Run warnings gathered by nested captures (a jackknife run inside a fit): the inner capture takes
// them while it lives, then the outer one gets the rest.
#include <doctest/doctest.h>

#include "src/io/run_warning.hpp"

using rollspec::io::RunWarningCapture;
using rollspec::io::warn;

TEST_CASE("run warnings: an inner capture hands warn() back to the outer one") {
  RunWarningCapture outer;
  warn("first");
  {
    const RunWarningCapture inner;
    warn("second", true);
    REQUIRE(inner.lines().size() == 1);
    CHECK(inner.lines()[0] == "rollspec: WARNING: second");
  }
  warn("third");
  REQUIRE(outer.lines().size() == 2);
  CHECK(outer.lines()[0] == "rollspec: warning: first");
  CHECK(outer.lines()[1] == "rollspec: warning: third");
}
