#pragma once
// The base of a section whose keys are declared once, in its `static SectionKeys<S> declare()`: keys() and
// parse() both come from that one list (built once, declared()), so a section writes its keys and nothing
// else per key. A section whose keys depend on each other (or that derives fields from them) gives
// `void finish()`, which parse calls once every key is read. The members are defined in section_keys.hpp;
// each section's .cpp instantiates them (`template struct DeclaredSection<BallSection>;`), so a section's
// header needs no parser.
#include <cstddef>
#include <string>
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
  // "section.key" of the key read into `field` (or into `inner` of the member `outer`). Code outside the
  // sections names a key by the member it is read into, never by its text: its name is written once, in
  // declare(), and a renamed or misspelt key fails to compile. logic_error for a member no key is read into.
  template <class T>
  static std::string key(T S::*field) {
    const S probe{};
    return key_at(offset_in(probe, &(probe.*field)));
  }
  template <class O, class T>
  static std::string key(O S::*outer, T O::*inner) {
    const S probe{};
    return key_at(offset_in(probe, &((probe.*outer).*inner)));
  }
  // The key read into the member at this byte offset of S.
  static std::string key_at(std::size_t offset);

 protected:
  void finish() {}

 private:
  static std::size_t offset_in(const S& s, const void* field) {
    return static_cast<std::size_t>(static_cast<const char*>(field) - reinterpret_cast<const char*>(&s));
  }
};

}  // namespace rollspec::study
