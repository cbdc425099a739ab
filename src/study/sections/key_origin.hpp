#pragma once
// Where a section's key got its value ("file:line: [section] key = value"), kept by the section
// parser so a check made later, once tables or the model are known, still names the key at fault
// (the message Study::refuse gives) without the Study.
#include <string>

#include "src/error.hpp"

namespace rollspec::study {

struct KeyOrigin {
  std::string where;
  [[noreturn]] void refuse(const std::string& why) const { throw config_error(where + ": " + why); }
};

}  // namespace rollspec::study
