#pragma once
// The study a command names: its file, its repeatable --set overrides, or its text (a sweep point).
#include <string>
#include <vector>

namespace rollspec::run {

struct StudyArgs {
  std::string file;
  std::vector<std::string> sets;
  std::string text;  // non-empty: the study's text, read instead of the file (a sweep point: no [sweep])
};

}  // namespace rollspec::run
