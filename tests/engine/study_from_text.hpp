#pragma once
// Engine doctests build their studies from INI text with the scenes' real key tables, as `run` loads
// a file: this header is where they meet the loader (src/study/study.hpp), so that the tests, like
// the engine, see the study through its typed sections.
#include <functional>
#include <string>
#include <vector>

#include "src/error.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

namespace rollspec::test {

inline study::Study study_from_text(const std::string& file, const std::string& text,
                                    const std::vector<std::string>& overrides = {}) {
  return study::Study::parse(file, text, overrides, scenes::schema_for);
}

// Studies of one scene in one file: lines 1-4 are [study] with the scene, `realisations` and `seed`, and the text a
// test adds starts at line 5.
struct SceneStudies {
  std::string file, scene;
  int realisations = 2, seed = 1;

  study::Study operator()(const std::string& extra, const std::vector<std::string>& overrides = {}) const {
    return study_from_text(file,
                           "[study]\nscene = " + scene + "\nrealisations = " + std::to_string(realisations) +
                               "\nseed = " + std::to_string(seed) + "\n" + extra,
                           overrides);
  }
};

// The message of the UserError that `f` throws ("" when it throws none): what a user would read.
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

}  // namespace rollspec::test
