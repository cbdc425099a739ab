#pragma once
// [analysis] and [output] of scene rolling-beam, read once: the step, the run length, the solver's
// limits and the recorded nodes. The step is checked against the run length here; the integrator
// against the model's beam elements by the scene, at origin(integrator).
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"
#include "src/study/sections/rolling_world_sections.hpp"

namespace rollspec::study {

class KeyReader;

enum class AnalysisType { dynamic, quasi_static };
enum class AnalysisIntegrator { newmark, energy_consistent };

inline constexpr ChoiceTable<AnalysisType, 2> kAnalysisTypes{{
    {AnalysisType::dynamic, "dynamic", "Newmark trapezoidal"},
    {AnalysisType::quasi_static, "static", "quasi-static load steps"},
}};
inline constexpr ChoiceTable<AnalysisIntegrator, 2> kAnalysisIntegrators{{
    {AnalysisIntegrator::newmark, "newmark", "trapezoidal"},
    {AnalysisIntegrator::energy_consistent, "energy-consistent",
     "midpoint + discrete-gradient penalty; rigid bodies only"},
}};

struct RollingAnalysisSection : DeclaredSection<RollingAnalysisSection> {
  AnalysisType type = AnalysisType::dynamic;
  AnalysisIntegrator integrator = AnalysisIntegrator::newmark;
  bool dynamic = true;             // type = dynamic (else quasi-static load steps)
  bool energy_consistent = false;  // integrator = energy-consistent (else Newmark)
  double dt = 0.0, t_end = 0.0, impact_step_fraction = 0.0, max_new_penetration = 0.0, tolerance = 0.0;
  long long record_every = 1, max_iterations = 0, max_cuts = 0, line_search = 0;

  static SectionKeys<RollingAnalysisSection> declare();
  void finish();  // dynamic, energy_consistent; dt against t_end
};

// [output] of rolling-beam: the recorded nodes.
struct NodeOutputSection : DeclaredSection<NodeOutputSection> {
  NodeList nodes;

  static SectionKeys<NodeOutputSection> declare();
};

}  // namespace rollspec::study
