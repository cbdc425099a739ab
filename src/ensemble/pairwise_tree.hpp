#pragma once
// The fixed summation order of an ensemble (theory E-1): realisation results are added along a
// binary tree over realisation ids, [lo, hi) split at lo + 2^p with 2^p the largest power of two
// below hi - lo. Every aligned block of 2^c ids (and the tail block) is a node of this tree, so
// chunk sums computed anywhere (any thread, rank, or an earlier interrupted run) combine to the
// same bits as one sequential pass over the tree. Pairwise summation also keeps the rounding
// error O(log K) instead of O(K).
#include <cstdint>
#include <functional>
#include <vector>

namespace rollspec::ensemble {

inline std::uint64_t tree_split(std::uint64_t lo, std::uint64_t hi) {
  std::uint64_t p = 1;
  while (p * 2 < hi - lo) p *= 2;
  return lo + p;
}

// Sum over [lo, hi): leaf(lo, hi) returns a node's sum when it can (a stored chunk, or a single
// realisation), or an empty vector to ask for a split.
std::vector<double> tree_sum(std::uint64_t lo, std::uint64_t hi,
                             const std::function<std::vector<double>(std::uint64_t, std::uint64_t)>& leaf);

}  // namespace rollspec::ensemble
