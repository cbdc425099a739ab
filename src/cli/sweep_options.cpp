#include "src/cli/sweep_options.hpp"

#include "src/run/run_phases.hpp"

namespace rollspec::cli {

void add_sweep_option(po::options_description& options, std::vector<std::string>& sweeps, std::size_t& max_points) {
  options.add_options()("sweep", po::value(&sweeps)->composing(),
                        "sweep a study key: --sweep section.key=v1,v2,... (repeatable; added to the study's [sweep])")(
      "max-points", po::value(&max_points)->default_value(run::kDefaultMaxSweepPoints),
      "the most points a sweep may have (each is one run and one file)");
}

}  // namespace rollspec::cli
