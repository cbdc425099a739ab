// A sweep stacks its points' /psd and /bands into one array each, so every point must give them
// one shape and one set of coordinates. The scene's settings fix both before anything runs: a swept
// key that changes them is refused here, by `plan` and by `run`, before the first point (the run's
// check after each point stays for what the settings cannot tell, e.g. a single-run scene). Each
// point's memory estimate is checked in the same pass: a point that cannot fit is refused before
// the first point runs, not when the sweep reaches it.
#include <optional>

#include "src/run/sweep_run.hpp"
#include "src/error.hpp"

namespace rollspec::run {

void check_sweep_points(const SweepStudy& s, bool force) {
  std::optional<scenes::ResultShape> first;
  for (std::size_t i = 0; i < s.points(); ++i) {
    const study::Study point = resolve_study(s.point(i));
    try {
      check_resources(point, force);
    } catch (const UserError& e) {
      throw UserError(e.exit_code(), "sweep point " + std::to_string(i + 1) + " of " + std::to_string(s.points()) +
                                         " (" + s.label(i) + "): " + e.what());
    }
    const scenes::SceneInfo& scene = scenes::find_scene(point.scene());
    if (!scene.result_shape) continue;
    const scenes::ResultShape shape = scene.result_shape(point);
    if (!first) first = shape;
    if (shape == *first) continue;
    // The keys whose values differ between the first point and this one are the ones at fault.
    const auto a = s.sweep.point_sets(0), b = s.sweep.point_sets(i);
    std::string where;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (a[k] != b[k]) where += (where.empty() ? "" : "; ") + s.sweep.keys[k].origin.where;
    throw config_error(where + ": its points differ in the shape or coordinates of the result, which a sweep " +
                       "stacks into one array: at " + s.label(0) + " " + first->text() + "; at " + s.label(i) + " " +
                       shape.text() +
                       "; allowed: keys that keep /psd and /bands (run such values as separate studies)");
  }
}

}  // namespace rollspec::run
