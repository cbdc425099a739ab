#pragma once
// Every cached table a study's scene shares (stiffness, blocked force, equivalent roughness, path
// table), reused or built as `rollspec run` does before its ensemble, and nothing else: no
// realisation runs and no result is written. rollspec.contact.tables returns them to Python.
#include <string>
#include <vector>

#include "src/study/study.hpp"

namespace rollspec::run {

struct StudyTable {
  std::string stage;   // the plan's stage name: stiffness_table, blocked_force, ...
  std::string path;    // the table file
  std::string status;  // "cached PATH" (reused) or "built PATH"
};

// After the run's checks (the memory estimate unless `force`); `rebuild` replaces a table whose inputs
// differ or that is damaged, which is refused otherwise. A study whose scene shares no table: none.
std::vector<StudyTable> study_tables(const study::Study& s, bool force, bool rebuild, bool quiet);

}  // namespace rollspec::run
