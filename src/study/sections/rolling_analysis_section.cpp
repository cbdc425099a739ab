#include "src/study/sections/rolling_analysis_section.hpp"

#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> RollingAnalysisSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("analysis", "type", "analysis type", AnalysisType::dynamic, kAnalysisTypes),
      real_key("analysis", "dt", "s", "time (load) step", std::string("1e-3"), 0.0, inf, false),
      real_key("analysis", "t_end", "s", "end time", std::string("1"), 0.0, inf, false),
      choice_key("analysis", "integrator", "dynamic integrator", AnalysisIntegrator::newmark, kAnalysisIntegrators),
      real_key("analysis", "impact_step_fraction", "-",
               "while a contact is closed or closing, limit the step to this fraction of 2 pi sqrt(m/eps_n) (0: off)",
               std::string("0"), 0.0, 1.0),
      real_key("analysis", "max_new_penetration", "m", "cut steps in which a contact closes deeper than this (0: off)",
               std::string("0"), 0.0, inf),
      integer_key("analysis", "record_every", "steps between recorded states", std::string("1"), 1, 1e9),
      integer_key("analysis", "max_iterations", "Newton iterations per step before cutting it", std::string("30"), 1,
                  10000),
      integer_key("analysis", "max_cuts", "step halvings allowed", std::string("12"), 0, 60),
      integer_key("analysis", "line_search", "backtracking halvings per Newton iteration", std::string("12"), 0, 60),
      real_key("analysis", "tolerance", "-",
               "Newton convergence: residual 2-norm relative to the body's weight (1 N without gravity)",
               std::string("1e-6"), 0.0, 1.0, false),
  };
}

RollingAnalysisSection RollingAnalysisSection::parse(const KeyReader& s) {
  RollingAnalysisSection a;
  a.dynamic = read_choice(s, "analysis.type", kAnalysisTypes) == AnalysisType::dynamic;
  a.energy_consistent =
      read_choice(s, "analysis.integrator", kAnalysisIntegrators) == AnalysisIntegrator::energy_consistent;
  a.integrator_origin = {s.where("analysis.integrator")};
  a.impact_step_fraction = s.real("analysis.impact_step_fraction");
  a.max_new_penetration = s.real("analysis.max_new_penetration");
  a.max_iterations = s.integer("analysis.max_iterations");
  a.max_cuts = s.integer("analysis.max_cuts");
  a.line_search = s.integer("analysis.line_search");
  a.tolerance = s.real("analysis.tolerance");
  a.dt = s.real("analysis.dt");
  a.t_end = s.real("analysis.t_end");
  if (a.dt > a.t_end) s.refuse("analysis.dt", "exceeds [analysis] t_end");
  if (a.t_end / a.dt > 1e8) s.refuse("analysis.dt", "gives more than 1e8 steps");
  a.record_every = s.integer("analysis.record_every");
  a.dt_origin = {s.where("analysis.dt")};
  return a;
}

std::vector<KeySpec> NodeOutputSection::keys() {
  return {text_key("output", "nodes", "recorded nodes: all, or comma-separated indices", std::string("all"))};
}

NodeOutputSection NodeOutputSection::parse(const KeyReader& s) {
  NodeOutputSection o;
  o.nodes.all = s.text("output.nodes") == "all";
  if (!o.nodes.all) o.nodes.indices = s.numbers("output.nodes");
  o.nodes.origin = {s.where("output.nodes")};
  return o;
}

}  // namespace rollspec::study
