#include "src/stiffness/stiffness_keys.hpp"

#include <limits>

namespace rollspec::stiffness {

using namespace study;

std::vector<KeySpec> stiffness_keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      text_key("stiffness", "table", "table file: auto (<table_dir>/stiffness-<input hash>.h5) or a path", std::string("auto")),
      text_key("stiffness", "table_dir", "directory of cached tables, relative to the study file", std::string("tables")),
      choice_key("stiffness", "surface", "rough: [surface] realisations of the [texture] PSD; smooth: a smooth flat",
                 std::string("rough"), {"rough", "smooth"}),
      choice_key("stiffness", "shape", "ball geometry: exact sphere or Hertz's paraboloid", std::string("sphere"),
                 {"sphere", "paraboloid"}),
      real_key("stiffness", "ball_rms", "m",
               "rms roughness of the ball (rough on rough: composite surface h_flat + h_ball, the ball's heights from "
               "the [texture] PSD's shape scaled to this rms); 0: smooth ball",
               std::string("0"), 0.0, inf),
      real_key("stiffness", "approach_max", "m", "largest approach from first contact", std::string("0.5e-6"), 0.0, inf, false),
      integer_key("stiffness", "steps", "approach steps (uniform, warm-started)", std::string("20"), 2, 10000),
      integer_key("stiffness", "realisations", "rough-surface realisations averaged", std::string("10"), 1, 100000),
      real_key("stiffness", "hardness", "Pa", "pressure cap H (plastic flow); 0: none (elastic)", std::string("0"), 0.0, inf),
      real_key("stiffness", "tolerance", "-", "stopping rule: relative complementarity error of each contact solve",
               std::string("1e-8"), 1e-15, 1e-2),
      integer_key("stiffness", "max_iterations", "CG iterations allowed per contact solve", std::string("20000"), 10, 1e7),
  };
}

}  // namespace rollspec::stiffness
