#include "src/ensemble/pairwise_tree.hpp"

#include <stdexcept>

namespace rollspec::ensemble {

std::vector<double> tree_sum(std::uint64_t lo, std::uint64_t hi,
                             const std::function<std::vector<double>(std::uint64_t, std::uint64_t)>& leaf) {
  std::vector<double> node = leaf(lo, hi);
  if (!node.empty()) return node;
  if (hi - lo < 2) throw std::logic_error("pairwise tree: no value for a single realisation");
  const std::uint64_t mid = tree_split(lo, hi);
  std::vector<double> left = tree_sum(lo, mid, leaf);
  const std::vector<double> right = tree_sum(mid, hi, leaf);
  for (std::size_t i = 0; i < left.size(); ++i) left[i] += right[i];
  return left;
}

void TreeAccumulator::push(std::uint64_t lo, std::uint64_t hi, std::vector<double> values) {
  if (!nodes_.empty() && nodes_.back().hi != lo) throw std::logic_error("tree accumulator: chunks out of order");
  nodes_.push_back({lo, hi, std::move(values)});
  while (nodes_.size() >= 2) {
    Node& left = nodes_[nodes_.size() - 2];
    const Node& right = nodes_.back();
    const std::uint64_t size = left.hi - left.lo;
    // Siblings: equal power-of-two sizes, the left one aligned to their parent. A shorter tail
    // chunk never merges here; tree_sum adds it at the end, as the tree does.
    if (right.hi - right.lo != size || (size & (size - 1)) != 0 || left.lo % (2 * size) != 0) break;
    for (std::size_t i = 0; i < left.values.size(); ++i) left.values[i] += right.values[i];
    left.hi = right.hi;
    nodes_.pop_back();
  }
}

}  // namespace rollspec::ensemble
