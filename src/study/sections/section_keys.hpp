#pragma once
// A section's keys, each declared once (deal.II's ParameterAcceptor::add_parameter): its name, the field it
// is read into, unit, range, default and documentation, and for a choice the ChoiceTable. The section's
// keys() (its KeySpecs: validation, `rollspec keys`, the templates and the reference docs) and its parse
// (reading every key into its field, recording each key's text and origin in the KeyedSection) both come
// from this one list (DeclaredSection, the sections' base, defined at the end). A field is a member pointer
// (&BallSection::radius) or, for a nested member, a function returning it. Used by the sections' .cpp files only.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/study/key_reader.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/declared_section.hpp"
#include "src/study/sections/keyed_section.hpp"

namespace rollspec::study {

// The allowed values of a number key.
struct Range {
  double min = -std::numeric_limits<double>::infinity(), max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true, max_inclusive = true;
};
inline Range above(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, true}; }
inline Range at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, true}; }
inline Range within(double lo, double hi) { return {lo, hi, true, true}; }
inline Range any_number() { return {}; }

// A comma-separated list of finite numbers (KeyReader::numbers), for text(key, field, doc, default, read).
inline std::vector<double> number_list(const KeyReader& s, const std::string& full_key) { return s.numbers(full_key); }

// The field `inner` of the member `outer` of a section (a key read into a nested struct's member).
template <class S, class M, class T>
auto nested(M S::*outer, T M::*inner) {
  return [outer, inner](S& s) -> T& { return (s.*outer).*inner; };
}

template <class S>
class SectionKeys {
 public:
  using Default = std::optional<std::string>;

  explicit SectionKeys(std::string section) : section_(std::move(section)) {}

  template <class F>
  SectionKeys& real(const char* key, F field, std::string unit, std::string doc, Default fallback, Range r) {
    return bind(real_key(section_, key, std::move(unit), std::move(doc), std::move(fallback), r.min, r.max,
                         r.min_inclusive, r.max_inclusive),
                field, [](const KeyReader& s, const std::string& k) { return s.real(k); });
  }
  template <class F>
  SectionKeys& integer(const char* key, F field, std::string doc, Default fallback, double min, double max) {
    return bind(integer_key(section_, key, std::move(doc), std::move(fallback), min, max), field,
                [](const KeyReader& s, const std::string& k) { return s.integer(k); });
  }
  template <class F>
  SectionKeys& boolean(const char* key, F field, std::string doc, Default fallback) {
    return bind(bool_key(section_, key, std::move(doc), std::move(fallback)), field,
                [](const KeyReader& s, const std::string& k) { return s.boolean(k); });
  }
  template <class F>
  SectionKeys& text(const char* key, F field, std::string doc, Default fallback) {
    return bind(text_key(section_, key, std::move(doc), std::move(fallback)), field,
                [](const KeyReader& s, const std::string& k) { return s.text(k); });
  }
  // A file key: the field holds the path usable from the current directory (its text, the path as written).
  template <class F>
  SectionKeys& path(const char* key, F field, std::string doc, Default fallback) {
    return bind(path_key(section_, key, std::move(doc), std::move(fallback)), field,
                [](const KeyReader& s, const std::string& k) { return s.path(k); });
  }
  // A text key read by `read(KeyReader, full key)` (a list of numbers, an x,y,z vector, ...).
  template <class F, class Read>
  SectionKeys& text(const char* key, F field, std::string doc, Default fallback, Read reader) {
    return bind(text_key(section_, key, std::move(doc), std::move(fallback)), field, reader);
  }
  template <class F, class E, std::size_t N>
  SectionKeys& choice(const char* key, F field, const std::string& lead, E fallback, const ChoiceTable<E, N>& table) {
    return bind(choice_key(section_, key, lead, fallback, table), field,
                [&table](const KeyReader& s, const std::string& k) { return read_choice(s, k, table); });
  }
  // The last key is read only when `pred(section so far)` holds (keys are read in declaration order).
  SectionKeys& when(std::function<bool(const S&)> pred) {
    bindings_.back().when = std::move(pred);
    return *this;
  }

  // The last (integer) key must be a power of two.
  SectionKeys& power_of_two() {
    bindings_.back().spec.power_of_two = true;
    return *this;
  }

  // The section is read only where the scene has its first key (a section some scenes leave out).
  SectionKeys& section_if_present() {
    optional_section_ = true;
    return *this;
  }
  // The last key is read only where the scene has it (a key some scenes leave out).
  SectionKeys& if_present() {
    bindings_.back().optional = true;
    return *this;
  }
  // The last key is listed by each scene that has it, with the scene's own doc and default (key_of), not in keys().
  SectionKeys& scene_declared() {
    bindings_.back().listed = false;
    return if_present();
  }

  std::vector<KeySpec> keys() const {
    std::vector<KeySpec> out;
    for (const auto& b : bindings_)
      if (b.listed) out.push_back(b.spec);
    return out;
  }
  // The KeySpecs of the keys read into `fields`, in that order (a scene's subset of the section).
  template <class... F>
  std::vector<KeySpec> keys_of(F... fields) const {
    return {binding_of(fields).spec...};
  }
  // "section.key" of the key read into `field` (for a --set text the engine writes).
  template <class F>
  std::string full_name(F field) const {
    return binding_of(field).spec.full_name();
  }

  // "section.key" of the key read into the member at `offset` bytes into S (DeclaredSection::key).
  std::string full_name_at(std::size_t offset) const {
    S probe;
    for (const auto& b : bindings_)
      if (static_cast<std::size_t>(static_cast<const char*>(b.address(probe)) -
                                   reinterpret_cast<const char*>(&probe)) == offset)
        return b.spec.full_name();
    throw std::logic_error("not a field a key of the section is read into");
  }

  // Every key into its field, in declaration order, each key's text and origin recorded.
  S read(const KeyReader& s) const {
    S out;
    read(s, out);
    return out;
  }
  void read(const KeyReader& s, S& out) const {
    KeyedSection& record = out;
    if (optional_section_ && !bindings_.empty() && !s.has(bindings_.front().spec.full_name())) return;
    for (const auto& b : bindings_) {
      if ((b.when && !b.when(out)) || (b.optional && !s.has(b.spec.full_name()))) continue;
      const std::string full = b.spec.full_name();
      b.read(s, full, out);
      record.key_values_.push_back(
          {b.spec.key, s.text(full), {s.where(full)}, s.is_set(full), record.offset_of(b.address(out))});
    }
  }

 private:
  struct Binding {
    KeySpec spec;
    std::function<void(const KeyReader&, const std::string&, S&)> read;
    std::function<const void*(S&)> address;
    std::function<bool(const S&)> when;
    bool optional = false, listed = true;
  };

  template <class F>
  const Binding& binding_of(F field) const {
    S probe;
    const void* address = &at(field, probe);
    for (const auto& b : bindings_)
      if (b.address(probe) == address) return b;
    throw std::logic_error("not a field a key of the section is read into");
  }

  template <class F>
  static auto& at(F field, S& s) {
    if constexpr (std::is_member_object_pointer_v<F>)
      return s.*field;
    else
      return field(s);
  }

  template <class F, class Read>
  SectionKeys& bind(KeySpec spec, F field, Read reader) {
    Binding b;
    b.spec = std::move(spec);
    b.read = [field, reader](const KeyReader& s, const std::string& k, S& out) {
      auto& target = at(field, out);
      target = static_cast<std::remove_reference_t<decltype(target)>>(reader(s, k));
    };
    b.address = [field](S& out) -> const void* { return &at(field, out); };
    bindings_.push_back(std::move(b));
    return *this;
  }

  std::string section_;
  std::vector<Binding> bindings_;
  bool optional_section_ = false;
};

template <class S>
const SectionKeys<S>& DeclaredSection<S>::declared() {
  static const SectionKeys<S> k = S::declare();
  return k;
}
template <class S>
std::string DeclaredSection<S>::key_at(std::size_t offset) {
  return declared().full_name_at(offset);
}
template <class S>
std::vector<KeySpec> DeclaredSection<S>::keys() {
  return declared().keys();
}
template <class S>
S DeclaredSection<S>::parse(const KeyReader& s) {
  S out = declared().read(s);
  out.finish();
  return out;
}

}  // namespace rollspec::study
