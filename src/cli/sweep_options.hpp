#pragma once
// The sweep options of run and plan: the repeatable --sweep section.key=v1,v2,..., and --max-points N.
#include <string>
#include <vector>

#include "src/cli/parse_options.hpp"

namespace rollspec::cli {

void add_sweep_option(po::options_description& options, std::vector<std::string>& sweeps, std::size_t& max_points);

}  // namespace rollspec::cli
