#pragma once
// What every table solved along a rough strip (blocked force, equivalent roughness, path table) does with
// its solves: refuse an unconverged one, and store positions along the path from the first.
#include <string>
#include <vector>

#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::stiffness {

// `what` did not converge: refused (exit 65) with the largest stopping-rule error and the keys that help.
inline void require_converged(bool converged, double max_error, const std::string& what) {
  if (!converged)
    throw data_error(what + " did not converge (largest error " + io::exact_text(max_error) +
                     "); raise [stiffness] max_iterations or tolerance");
}

// Strip coordinates as the path coordinate the tables store: from the first position.
inline std::vector<double> from_first(const std::vector<double>& x) {
  std::vector<double> out;
  out.reserve(x.size());
  for (double v : x) out.push_back(v - x.front());
  return out;
}

}  // namespace rollspec::stiffness
