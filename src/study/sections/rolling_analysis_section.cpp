#include "src/study/sections/rolling_analysis_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<RollingAnalysisSection> RollingAnalysisSection::declare() {
  using T = RollingAnalysisSection;
  return SectionKeys<T>("analysis")
      .choice("type", &T::type, "analysis type", AnalysisType::dynamic, kAnalysisTypes)
      .real("dt", &T::dt, "s", "time (load) step", "1e-3", above(0.0))
      .real("t_end", &T::t_end, "s", "end time", "1", above(0.0))
      .choice("integrator", &T::integrator, "dynamic integrator", AnalysisIntegrator::newmark, kAnalysisIntegrators)
      .real("impact_step_fraction", &T::impact_step_fraction, "-",
            "while a contact is closed or closing, limit the step to this fraction of 2 pi sqrt(m/eps_n) (0: off)", "0",
            within(0.0, 1.0))
      .real("max_new_penetration", &T::max_new_penetration, "m",
            "cut steps in which a contact closes deeper than this (0: off)", "0", at_least(0.0))
      .integer("record_every", &T::record_every, "steps between recorded states", "1", 1, 1e9)
      .integer("max_iterations", &T::max_iterations, "Newton iterations per step before cutting it", "30", 1, 10000)
      .integer("max_cuts", &T::max_cuts, "step halvings allowed", "12", 0, 60)
      .integer("line_search", &T::line_search, "backtracking halvings per Newton iteration", "12", 0, 60)
      .real("tolerance", &T::tolerance, "-",
            "Newton convergence: residual 2-norm relative to the body's weight (1 N without gravity)", "1e-6",
            {0.0, 1.0, false});
}
template struct DeclaredSection<RollingAnalysisSection>;

SectionKeys<NodeOutputSection> NodeOutputSection::declare() {
  using T = NodeOutputSection;
  return SectionKeys<T>("output").text("nodes", &T::nodes, "recorded nodes: all, or comma-separated indices", "all",
                                       node_list);
}
template struct DeclaredSection<NodeOutputSection>;

void RollingAnalysisSection::finish() {
  dynamic = type == AnalysisType::dynamic;
  energy_consistent = integrator == AnalysisIntegrator::energy_consistent;
  if (dt > t_end) origin(dt).refuse("exceeds [analysis] t_end");
  if (t_end / dt > 1e8) origin(dt).refuse("gives more than 1e8 steps");
}

}  // namespace rollspec::study
