#include "src/cli/plan_tables.hpp"

#include <cstdio>
#include <limits>

#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/study/sections/contact_section.hpp"

namespace rollspec::cli {

bool table_stage(const study::Study& s, const scenes::StagePlan& stage) {
  if (stage.stage == "stiffness_table" || stage.stage == "equivalent_roughness" || stage.stage == "path_table")
    return true;
  // Only ball-on-beam has a blocked-force stage; it is a table with [contact] blocked_force = solver.
  return stage.stage == "blocked_force" && s.scene() == "ball-on-beam" &&
         study::ContactSection::parse(s).blocked_force == study::BlockedForceSource::solver;
}

bool missing_table(const study::Study& s, const scenes::StagePlan& stage) {
  return stage.status == scenes::StageStatus::run && table_stage(s, stage);
}

bool any_missing_table(const study::Study& s, const std::vector<scenes::StagePlan>& stages) {
  for (const auto& p : stages)
    if (missing_table(s, p)) return true;
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
