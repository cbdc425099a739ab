#pragma once
// The documented keys of a study: type, unit, allowed range, default and meaning of each.
// Validation, the resolved-study echo and `rollspec keys` all read this one table.
#include <array>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rollspec::study {

enum class KeyType { real, integer, text, choice, path, boolean };

struct KeySpec {
  std::string section;
  std::string key;
  KeyType type = KeyType::real;
  std::string unit = "-";                    // SI unit of the value, "-" for none
  std::string doc;                           // one line: what the key means
  std::optional<std::string> default_value;  // nullopt: the key is required
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  bool max_inclusive = true;
  std::vector<std::string> choices;  // for KeyType::choice
  bool power_of_two = false;         // for KeyType::integer

  std::string full_name() const { return section + "." + key; }
  std::string allowed() const;  // human text: "a number > 0 (Hz)", "one of hann, rectangular", ...
};

// Builders that keep scene schemas short and readable.
KeySpec real_key(std::string section, std::string key, std::string unit, std::string doc,
                 std::optional<std::string> default_value, double min, double max, bool min_inclusive = true,
                 bool max_inclusive = true);
KeySpec integer_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                    double min, double max);
KeySpec choice_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                   std::vector<std::string> choices);
KeySpec text_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);
KeySpec path_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);
KeySpec bool_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value);

// The keys of several sections one after the other, in the order given (a scene's schema).
std::vector<KeySpec> joined_keys(std::initializer_list<std::vector<KeySpec>> parts);

// One allowed value of a choice key: the enum value code switches on, its spelling in a study and a
// short doc (empty: the spelling says it). A section declares one table per choice; the key's allowed
// values (errors, `rollspec keys`, the reference docs) and its parsing (sections/choice_read.hpp) both
// read that table, so a value cannot be allowed and then fall through unhandled.
template <class E>
struct Choice {
  E value;
  const char* spelling;
  const char* doc;
};

template <class E, std::size_t N>
using ChoiceTable = std::array<Choice<E>, N>;

// "lead: a (doc a), b or c (doc c)"; the lead alone when no value has a doc.
std::string choice_doc(const std::string& lead, const std::vector<std::string>& spellings,
                       const std::vector<std::string>& docs);

// The choice key of a table, its default one of the table's values.
template <class E, std::size_t N>
KeySpec choice_key(std::string section, std::string key, const std::string& lead, E default_value,
                   const ChoiceTable<E, N>& table) {
  std::vector<std::string> spellings, docs;
  std::optional<std::string> fallback;
  for (const auto& c : table) {
    spellings.emplace_back(c.spelling);
    docs.emplace_back(c.doc);
    if (c.value == default_value) fallback = c.spelling;
  }
  std::string doc = choice_doc(lead, spellings, docs);  // before the spellings move
  return choice_key(std::move(section), std::move(key), std::move(doc), fallback, std::move(spellings));
}

// The spelling of a value in its table (for messages and canonical texts).
template <class E, std::size_t N>
std::string spelling_of(const ChoiceTable<E, N>& table, E value) {
  for (const auto& c : table)
    if (c.value == value) return c.spelling;
  return "?";  // not reached while the table has a row for every value it is asked about
}

// "section.key=spelling": a --set text naming a choice by its table's spelling, for the runs the engine
// derives from a study (the closed-contact and sub-table runs), so they cannot drift from the key's values.
template <class E, std::size_t N>
std::string choice_setting(const std::string& full_key, const ChoiceTable<E, N>& table, E value) {
  return full_key + "=" + spelling_of(table, value);
}

}  // namespace rollspec::study
