#pragma once
// Scene `rolling-beam`'s study keys and their reading, once, into the model they describe (a
// beam, a disc or one of seed 000's builders on planes), the solver and run options, with the
// checks that span several keys (normals per point, clamps of a disc, imposed series, the
// integrator against beam elements, the step against the run length).
#include <string>
#include <vector>

#include "kernels/rolling/examples.hpp"
#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "src/study/key_spec.hpp"

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

std::vector<study::KeySpec> rolling_beam_keys();

struct RollingBeamSettings {
  rolling::Model model;
  rolling::SolverOptions solver;
  rolling::RunOptions run;
  std::vector<int> record;           // recorded nodes
  rolling::FlyingBeamParams flying;  // kind = flying-beam
  std::string step_where;            // "file:line: [analysis] dt = ..." for a run that fails
  long long elements = 0;            // [beam] elements of a straight beam (0: the kind has none)
};

RollingBeamSettings read_rolling_beam_settings(const study::KeyReader& s);

}  // namespace rollspec::scenes
