// The reference table (src/io/references.cpp) and the ids the scenes, tables and compare take from it:
// every id any study's choices can give is in the table (an id missing from it is an internal error at
// write time), each row quotes cleanly as "id | citation | doi", and DOIs look like DOIs.
#include <doctest/doctest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "src/compare/verdict_references.hpp"
#include "src/io/references.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "tests/engine/study_from_text.hpp"

using namespace rollspec;

TEST_CASE("references: ids unique, no separator in a row, a DOI starts 10.") {
  std::set<std::string> ids;
  for (const auto& r : io::reference_table()) {
    CHECK(ids.insert(r.id).second);
    CHECK(std::string(r.id).find('|') == std::string::npos);
    CHECK(std::string(r.citation).find('|') == std::string::npos);
    const std::string doi = r.doi;
    CHECK((doi.empty() || (doi.rfind("10.", 0) == 0 && doi.find(' ') == std::string::npos)));
  }
  CHECK_THROWS_AS(io::find_reference("D-999"), std::logic_error);
  CHECK(io::reference_lines({"D-1", "D-1"}).size() == 1);  // each once
}

TEST_CASE("references: every ball-on-beam law and filter the study accepts names rows of the table") {
  int accepted = 0;
  for (const char* law : {"hertz", "table", "literal", "linearised", "path"})
    for (const char* source : {"spring", "solver"})
      for (const char* filter : {"none", "patch", "iso2d", "solver"}) {
        const std::string text = "[study]\nscene = ball-on-beam\nrealisations = 5\nseed = 1\n";
        const std::vector<std::string> sets = {std::string("contact.law=") + law,
                                               std::string("contact.blocked_force=") + source,
                                               std::string("contact.filter=") + filter};
        std::vector<std::string> ids;
        try {
          ids = scenes::study_references(test::study_from_text("/tmp/rollspec_references.ini", text, sets));
        } catch (const UserError&) {
          continue;  // a combination the scene refuses
        }
        ++accepted;
        CAPTURE(law);
        CAPTURE(filter);
        CHECK_NOTHROW(io::reference_lines(ids));
        CHECK(std::set<std::string>(ids.begin(), ids.end()).count("D-21") == 1);  // 5 realisations: an interval
      }
  CHECK(accepted >= 10);
}

TEST_CASE("references: the tables' and compare's ids are rows of the table") {
  for (const auto* kind : {&stiffness::kStiffnessTableKind, &stiffness::kBlockedForceTableKind,
                           &stiffness::kEquivalentRoughnessTableKind, &stiffness::kPathTableKind})
    CHECK_NOTHROW(io::reference_lines(kind->references));
  compare::Verdict v;
  v.test.result.defined = true;
  v.test.result.draws = 10;
  CHECK_NOTHROW(io::reference_lines(compare::verdict_references(v, true, true)));
  v.test.result.draws = 0;
  CHECK_NOTHROW(io::reference_lines(compare::verdict_references(v, false, false)));
}
