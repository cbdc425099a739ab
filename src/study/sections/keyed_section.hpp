#pragma once
// What a section's parse recorded of each key it declares (section_keys.hpp): the canonical text, where the
// value came from and whether the study set it, found later by the field the key was read into
// (`ball.origin(ball.end)`), so no key is named again after its one declaration.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

struct KeyValue {
  std::string key;   // the key's name in its section
  std::string text;  // canonical text of the value (as the resolved study writes it)
  KeyOrigin origin;
  bool set = false;           // the study file or a --set gave it (false: the documented default)
  std::uintptr_t offset = 0;  // of the field it was read into, from the KeyedSection
};

// The base of a section whose keys are declared once: the keys' values as read, in declaration order.
class KeyedSection {
 public:
  template <class T>
  const KeyOrigin& origin(const T& field) const {
    return value_of(&field).origin;
  }
  template <class T>
  const std::string& value_text(const T& field) const {
    return value_of(&field).text;
  }
  template <class T>
  bool was_set(const T& field) const {
    return value_of(&field).set;
  }
  template <class T>
  const KeyValue& key_value(const T& field) const {
    return value_of(&field);
  }
  const std::vector<KeyValue>& key_values() const { return key_values_; }
  // Whether `v` (of key_values()) is the key read into `field`.
  template <class T>
  bool is_of(const KeyValue& v, const T& field) const {
    return v.offset == offset_of(&field);
  }

 protected:
  // A value the section changed after the parse (a sub-table's own settings) gets the text it would have been read
  // from, so the canonical texts stay the section's values.
  template <class T>
  void set_text(const T& field, std::string text) {
    const std::uintptr_t offset = offset_of(&field);
    for (auto& v : key_values_)
      if (v.offset == offset) v.text = std::move(text);
  }

 private:
  template <class S>
  friend class SectionKeys;
  std::uintptr_t offset_of(const void* field) const {
    return reinterpret_cast<std::uintptr_t>(field) - reinterpret_cast<std::uintptr_t>(this);
  }
  const KeyValue& value_of(const void* field) const {
    const std::uintptr_t offset = offset_of(field);
    for (const auto& v : key_values_)
      if (v.offset == offset) return v;
    throw std::logic_error("not a field a key of the section was read into");
  }
  std::vector<KeyValue> key_values_;
};

}  // namespace rollspec::study
