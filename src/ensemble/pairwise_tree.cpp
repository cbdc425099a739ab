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

}  // namespace rollspec::ensemble
