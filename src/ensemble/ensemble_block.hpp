#pragma once
// One ensemble that runs several scenes side by side on the same streams (the table jackknife's sub-tables,
// D-30c; the closed-contact run, D-35) lays each scene's values out as block i of nv values: block i's sums
// are that scene's own ensemble sums.
#include <cstddef>

#include "src/ensemble/ensemble_driver.hpp"

namespace rollspec::ensemble {

inline EnsembleSums block_sums(const EnsembleSums& all, std::size_t i, std::size_t nv) {
  EnsembleSums b;
  const auto first = static_cast<std::ptrdiff_t>(i * nv), last = static_cast<std::ptrdiff_t>((i + 1) * nv);
  b.sum.assign(all.sum.begin() + first, all.sum.begin() + last);
  b.sum_sq.assign(all.sum_sq.begin() + first, all.sum_sq.begin() + last);
  b.count = all.count;
  b.computed = all.computed;
  b.seconds = all.seconds;
  return b;
}

}  // namespace rollspec::ensemble
