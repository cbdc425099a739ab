#pragma once
// The fixed summation order of an ensemble (theory E-1): realisation results are added along a
// binary tree over realisation ids, [lo, hi) split at lo + 2^p with 2^p the largest power of two
// below hi - lo. Every aligned block of 2^c ids (and the tail block) is a node of this tree, so
// chunk sums computed anywhere (any thread, rank, or an earlier interrupted run) combine to the
// same bits as one sequential pass over the tree. Pairwise summation also keeps the rounding
// error O(log K) instead of O(K).
#include <cstdint>
#include <functional>
#include <map>
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

// Adds chunk sums as they complete, in increasing lo, without keeping them all: a node merges
// with its left sibling (same size, the pair aligned to twice it) as soon as both exist, which is
// the addition tree_sum makes for their parent, so the bits are those of tree_sum over the stored
// nodes. Chunks [lo, lo + C) pushed in order of a contiguous range leave at most about
// 2 log2(range / C) nodes (the aligned blocks that tile the range), whatever the chunk count.
class TreeAccumulator {
 public:
  struct Node {
    std::uint64_t lo = 0, hi = 0;
    std::vector<double> values;
  };
  // Chunks must come in increasing lo, each starting where the previous one ended.
  void push(std::uint64_t lo, std::uint64_t hi, std::vector<double> values);
  const std::vector<Node>& nodes() const { return nodes_; }
  std::size_t size() const { return nodes_.size(); }

 private:
  std::vector<Node> nodes_;
};

}  // namespace rollspec::ensemble
