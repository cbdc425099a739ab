#include "src/cli/plan_tables.hpp"

#include <cstdio>
#include <limits>

#include "src/stiffness/equivalent_roughness_table.hpp"

namespace rollspec::cli {

bool missing_table(const scenes::StagePlan& stage) { return stage.status == scenes::StageStatus::run && stage.table; }

bool any_missing_table(const std::vector<scenes::StagePlan>& stages) {
  for (const auto& p : stages)
    if (missing_table(p)) return true;
  return false;
}

double table_probe_limit(bool probe) {
  return probe ? std::numeric_limits<double>::infinity() : stiffness::kQuickProbeSeconds;
}

std::string table_probe_line(const scenes::TableEstimate& t) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "table %s: about %.2g s CPU, %.2g s wall on %d thread%s (probe: ", t.table.c_str(),
                t.seconds, t.seconds / t.threads, t.threads, t.threads == 1 ? "" : "s");
  return buf + t.how + ")";
}

}  // namespace rollspec::cli
