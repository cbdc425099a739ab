#include "src/study/key_spec.hpp"

#include "src/io/number_text.hpp"

#include <cmath>
#include <sstream>

namespace rollspec::study {

std::string KeySpec::allowed() const {
  std::ostringstream s;
  switch (type) {
    case KeyType::real:
    case KeyType::integer: {
      s << (type == KeyType::real ? "a finite number" : "a whole number");
      const bool lo = std::isfinite(min), hi = std::isfinite(max);
      if (lo && hi) {
        s << " in " << (min_inclusive ? "[" : "(") << io::significant_text(min, 12) << ", "
          << io::significant_text(max, 12) << (max_inclusive ? "]" : ")");
      } else if (lo) {
        s << (min_inclusive ? " >= " : " > ") << io::significant_text(min, 12);
      } else if (hi) {
        s << (max_inclusive ? " <= " : " < ") << io::significant_text(max, 12);
      }
      if (power_of_two) s << ", a power of two";
      if (unit != "-") s << " (" << unit << ")";
      break;
    }
    case KeyType::choice: {
      s << "one of ";
      for (std::size_t i = 0; i < choices.size(); ++i) s << (i ? ", " : "") << choices[i];
      break;
    }
    case KeyType::text:
      s << "text";
      break;
    case KeyType::path:
      s << "the path of an existing file (relative to the study file), or none";
      break;
    case KeyType::boolean:
      s << "true or false";
      break;
  }
  return s.str();
}

namespace {
// What every kind of key has: where it lives, its type, its text and its default.
KeySpec base_key(std::string section, std::string key, KeyType type, std::string doc,
                 std::optional<std::string> default_value) {
  KeySpec k;
  k.section = std::move(section);
  k.key = std::move(key);
  k.type = type;
  k.doc = std::move(doc);
  k.default_value = std::move(default_value);
  return k;
}
}  // namespace

KeySpec real_key(std::string section, std::string key, std::string unit, std::string doc,
                 std::optional<std::string> default_value, double min, double max, bool min_inclusive,
                 bool max_inclusive) {
  KeySpec k = base_key(std::move(section), std::move(key), KeyType::real, std::move(doc), std::move(default_value));
  k.unit = std::move(unit);
  k.min = min;
  k.max = max;
  k.min_inclusive = min_inclusive;
  k.max_inclusive = max_inclusive;
  return k;
}

KeySpec integer_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                    double min, double max) {
  KeySpec k = real_key(std::move(section), std::move(key), "-", std::move(doc), std::move(default_value), min, max);
  k.type = KeyType::integer;
  return k;
}

std::vector<KeySpec> joined_keys(std::initializer_list<std::vector<KeySpec>> parts) {
  std::vector<KeySpec> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

std::string choice_doc(const std::string& lead, const std::vector<std::string>& spellings,
                       const std::vector<std::string>& docs) {
  bool any = false;
  for (const auto& d : docs) any = any || !d.empty();
  if (!any) return lead;
  std::string out = lead + ": ";
  for (std::size_t i = 0; i < spellings.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == spellings.size() ? " or " : ", ") + spellings[i];
    if (!docs[i].empty()) out += " (" + docs[i] + ")";
  }
  return out;
}

KeySpec choice_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value,
                   std::vector<std::string> choices) {
  KeySpec k = base_key(std::move(section), std::move(key), KeyType::choice, std::move(doc), std::move(default_value));
  k.choices = std::move(choices);
  return k;
}

KeySpec text_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value) {
  return base_key(std::move(section), std::move(key), KeyType::text, std::move(doc), std::move(default_value));
}

KeySpec path_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value) {
  return base_key(std::move(section), std::move(key), KeyType::path, std::move(doc), std::move(default_value));
}

KeySpec bool_key(std::string section, std::string key, std::string doc, std::optional<std::string> default_value) {
  return base_key(std::move(section), std::move(key), KeyType::boolean, std::move(doc), std::move(default_value));
}

}  // namespace rollspec::study
