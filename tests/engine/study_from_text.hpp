#pragma once
// Engine doctests build their studies from INI text with the scenes' real key tables, as `run` loads
// a file: this header is where they meet the loader (src/study/study.hpp), so that the tests, like
// the engine, see the study through its typed sections.
#include <string>
#include <vector>

#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

namespace rollspec::test {

inline study::Study study_from_text(const std::string& file, const std::string& text,
                                    const std::vector<std::string>& overrides = {}) {
  return study::Study::parse(file, text, overrides, scenes::schema_for);
}

}  // namespace rollspec::test
