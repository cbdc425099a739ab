#pragma once
// `[equivalent_roughness] line = strip` (issue 19): h_eq (kernels/contact ER-1, ER-2) of strip 0
// itself along the ball's whole path, on the grid and at the positions of the path table
// (PathTableGeometry: cell, window, step, strip), so that the point law on h_eq and `law = path`
// roll over the same strip: the comparison that validates the equivalent-roughness model
// (kernels/contact README "Equivalent roughness", the path law B41-B46). Stored as an
// EquivalentRoughnessTable (one strip; its PSD is that strip's Welch PSD of h_eq) with its own
// input hash, cached like every table.
#include <string>

#include "src/stiffness/cached_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"

namespace rollspec::stiffness {

// The plan's row: strip, positions, window, estimate.
std::string strip_equivalent_roughness_describe(const PathTableGeometry& g);

CachedTable strip_equivalent_roughness_cached_table(const TableStudy& ts, const PathTableGeometry& g, double radius,
                                                    double effective_modulus, double load);

// position: xi_k - xi_0 (m, from the traverse's start, as PathTableData), height: h_eq(xi_k).
EquivalentRoughnessTable build_strip_equivalent_roughness(const TableStudy& ts, const PathTableGeometry& g,
                                                          double radius, double effective_modulus, double load,
                                                          bool quiet);

}  // namespace rollspec::stiffness
