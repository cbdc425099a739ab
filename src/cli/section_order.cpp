#include "src/cli/section_order.hpp"

namespace rollspec::cli {

std::vector<SectionKeys> group_by_section(const std::vector<study::KeySpec>& keys) {
  std::vector<SectionKeys> out;
  for (const auto& k : keys) {
    auto it = out.begin();
    while (it != out.end() && it->section != k.section) ++it;
    if (it == out.end()) it = out.insert(out.end(), SectionKeys{k.section, {}});
    it->keys.push_back(k);
  }
  return out;
}

}  // namespace rollspec::cli
