#pragma once
// Several sections read from one study in the order given (the first bad key is the one reported), each by
// its own T::parse: a scene names the sections it uses once.
#include "src/study/key_reader.hpp"

namespace rollspec::study {

template <class... Section>
void parse_sections(const KeyReader& s, Section&... sections) {
  ((sections = Section::parse(s)), ...);
}

}  // namespace rollspec::study
