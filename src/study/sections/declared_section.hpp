#pragma once
// The base of a section whose keys are declared once, in its `static SectionKeys<S> declare()`: keys() and
// parse() both come from that one list (built once, declared()), so a section writes its keys and nothing
// else per key. A section whose keys depend on each other (or that derives fields from them) gives
// `void finish()`, which parse calls once every key is read. The members are defined in section_keys.hpp;
// each section's .cpp instantiates them (`template struct DeclaredSection<BallSection>;`), so a section's
// header needs no parser.
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/keyed_section.hpp"

namespace rollspec::study {

class KeyReader;
template <class S>
class SectionKeys;

template <class S>
struct DeclaredSection : KeyedSection {
  static std::vector<KeySpec> keys();
  static S parse(const KeyReader& s);
  static const SectionKeys<S>& declared();

 protected:
  void finish() {}
};

}  // namespace rollspec::study
