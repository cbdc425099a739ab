#pragma once
// A scene's key table grouped by section: sections in the order they first appear, keys in table
// order within each. A scene's keys may add to a common section ([spectrum] skip_start), so the
// table itself can hold a section in several runs.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"

namespace rollspec::cli {

struct SectionKeys {
  std::string section;
  std::vector<study::KeySpec> keys;
};

std::vector<SectionKeys> group_by_section(const std::vector<study::KeySpec>& keys);

}  // namespace rollspec::cli
