#include "src/compare/verdict_references.hpp"

namespace rollspec::compare {

std::vector<std::string> verdict_references(const Verdict& v, bool recordings, bool predict) {
  std::vector<std::string> ids = {"D-32", "D-33", "D-17"};
  if (recordings) ids.insert(ids.end(), {"Welch 1967", "D-15"});
  if (predict) ids.push_back("D-22");
  if (v.test.result.defined) ids.push_back(v.test.result.draws > 0 ? "D-31" : "D-26");
  if (v.offset) ids.push_back("D-34");
  return ids;
}

}  // namespace rollspec::compare
