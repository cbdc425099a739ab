#pragma once
// `rollspec stiffness`'s work on a loaded study: its contact stiffness table reused or built
// (stiffness_table.hpp's resolve_table) for the ball and the surface its scene presses together, after
// the same checks as a run (a scene with a contact table, the memory estimate). The command prints
// the answer (src/cli/stiffness_command.cpp); rollspec.contact.stiffness_table returns it to Python.
#include <string>

#include "src/scenes/scene.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/study/study.hpp"

namespace rollspec::run {

struct StudyStiffnessTable {
  stiffness::StiffnessTable table;
  scenes::BallContact pair;  // the ball's radius, E* and weight the table was built for
  std::string path;          // the table file, where the study's [stiffness] table puts it
  std::string status;        // what resolve_table did: reused, built or rebuilt
};

// Refuses (UserError) a study whose scene has no contact table, or whose memory estimate exceeds the
// available memory unless `force`; `rebuild` replaces a table whose inputs differ or that is damaged.
StudyStiffnessTable study_stiffness_table(const study::Study& s, bool force, bool rebuild, bool quiet);

}  // namespace rollspec::run
