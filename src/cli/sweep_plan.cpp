// rollspec plan of a sweep: the points, each point's stages (a table every point needs appears
// under the same name and status at each, and is built once: cached tables are keyed by their
// inputs' hash), the probes of missing tables, and with --probe the time of the whole sweep.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "src/cli/plan_tables.hpp"
#include "src/cli/sweep_plan.hpp"
#include "src/run/sweep_run.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::cli {

using run::check_resources;
using run::make_scene;
using run::resolve_study;
using run::SweepStudy;

namespace {

// Seconds of one ensemble point from realisation 0; < 0 if it cannot be probed (tables not built, single run).
double probe_point(const study::Study& s, scenes::EnsembleScene* ensemble_scene,
                   const std::vector<scenes::StagePlan>& stages) {
  if (!ensemble_scene) return -1;
  if (any_missing_table(stages)) return -1;
  ensemble_scene->prepare(true, false);
  std::vector<double> values(ensemble_scene->values_per_realisation());
  const auto start = std::chrono::steady_clock::now();
  ensemble_scene->run_realisation(0, 0, values.data());
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t * static_cast<double>(study::StudySection::parse(s).realisations) / ensemble::ensemble_threads();
}

}  // namespace

int plan_sweep(const SweepStudy& sweep, bool probe) {
  const std::size_t n = sweep.points();
  std::cout << "sweep of " << sweep.args.file << ": " << (sweep.sweep.zipped ? "zipped" : "crossed") << ", " << n
            << " point" << (n == 1 ? "" : "s") << ", every point with the study's seed (common random numbers)\n";
  for (std::size_t i = 0; i < n; ++i) std::cout << "  point " << i + 1 << ": " << sweep.label(i) << "\n";
  std::vector<scenes::StagePlan> first;
  std::vector<std::pair<std::string, std::string>> tables;  // (stage: reason, points) in first-seen order
  double total = 0;
  bool probed = probe;
  std::vector<std::string> probed_tables, probe_lines;
  for (std::size_t i = 0; i < n; ++i) {
    const study::Study s = resolve_study(sweep.point(i));
    check_resources(s, false);
    const auto scene = make_scene<scenes::Scene>(s);
    const auto stages = scene->plan();
    std::cout << "point " << i + 1 << " (" << sweep.label(i) << "):";
    bool same = i > 0 && stages.size() == first.size();
    for (std::size_t k = 0; same && k < stages.size(); ++k)
      same = stages[k].status == first[k].status && stages[k].reason == first[k].reason;
    if (same) {
      std::cout << " the same stages as point 1\n";
    } else {
      std::cout << "\n";
      for (const auto& p : stages)
        std::printf("  %-16s %-8s %s\n", p.stage.c_str(), scenes::status_name(p.status), p.reason.c_str());
    }
    if (i == 0) first = stages;
    for (const auto& p : stages) {
      if (!p.table || p.status == scenes::StageStatus::skipped) continue;
      const std::string what = p.stage + ": " + p.reason;
      auto it = std::find_if(tables.begin(), tables.end(), [&](const auto& t) { return t.first == what; });
      if (it == tables.end()) it = tables.insert(tables.end(), {what, ""});
      it->second += (it->second.empty() ? "" : ", ") + std::to_string(i + 1);
    }
    auto* ensemble_scene = dynamic_cast<scenes::EnsembleScene*>(scene.get());
    // The missing tables a few real solves estimate better than the model: once per table file (the
    // stage's reason names it), under the first point that needs it; a point whose missing tables were
    // all seen at earlier points is not probed again.
    std::vector<std::string> missing;
    for (const auto& p : stages)
      if (missing_table(p)) missing.push_back(p.stage + ": " + p.reason);
    const auto seen = [&](const std::string& what) {
      return std::find(probed_tables.begin(), probed_tables.end(), what) != probed_tables.end();
    };
    if (ensemble_scene && !std::all_of(missing.begin(), missing.end(), seen)) {
      for (const auto& t : ensemble_scene->probe_tables(table_probe_limit(probe))) {
        const auto stage =
            std::find_if(stages.begin(), stages.end(), [&](const auto& p) { return p.stage == t.table; });
        if (stage == stages.end() || seen(t.table + ": " + stage->reason)) continue;
        probe_lines.push_back("  point " + std::to_string(i + 1) + ": " + table_probe_line(t));
      }
      probed_tables.insert(probed_tables.end(), missing.begin(), missing.end());
    }
    if (probe && probed) {
      const double t = probe_point(s, ensemble_scene, stages);
      probed = t >= 0;
      total += t;
    }
  }
  // Cached tables are named by the hash of their inputs: points that name the same table share one build.
  if (!tables.empty()) std::cout << "tables (one build each, shared by the points listed):\n";
  for (const auto& [what, points] : tables) std::cout << "  points " << points << ": " << what << "\n";
  if (!probe_lines.empty()) std::cout << "tables probed (a few of their solves timed):\n";
  for (const auto& line : probe_lines) std::cout << line << "\n";
  if (!probe) return 0;
  if (!probed)
    std::cout << "run time: not probed (a point is one deterministic run, or its stage tables are not built yet)\n";
  else
    std::printf(
        "run time: about %.3g s for the %zu points on %d thread(s) (probe of realisation 0 of each point; "
        "plus stage tables and the final writes)\n",
        total, n, ensemble::ensemble_threads());
  return 0;
}

}  // namespace rollspec::cli
