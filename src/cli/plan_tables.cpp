#include "src/cli/plan_tables.hpp"
#include "src/io/number_text.hpp"

#include <cstdio>

namespace rollspec::cli {

std::string table_probe_line(const scenes::TableEstimate& t) {
  const std::string buf =
      io::formatted("table %s: about %.2g s CPU, %.2g s wall on %d thread%s (probe: ", t.table.c_str(), t.seconds,
                    t.seconds / t.threads, t.threads, t.threads == 1 ? "" : "s");
  return buf + t.how + ")";
}

}  // namespace rollspec::cli
