#include "src/io/measurement_unit.hpp"

#include <cctype>
#include <utility>

#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {
// One spelling: superscripts, micro signs and multiplication dots (UTF-8, then the ISO-8859-1 bytes
// a Windows export writes) to ASCII; blanks, '*', '^' and '.' dropped; lower case.
std::string normalise(const std::string& in) {
  static const std::pair<const char*, const char*> kUtf8[] = {
      {"\xC2\xB2", "2"},     {"\xC2\xB3", "3"},     {"\xC2\xB5", "u"},       {"\xCE\xBC", "u"},
      {"\xE2\x81\xBB", "-"}, {"\xE2\x88\x92", "-"}, {"\xC2\xB7", "*"},       {"\xE2\x8B\x85", "*"},
      {"\xE2\x80\xA2", "*"}, {"\xC2\xB0", "deg"},   {"\xE2\x84\x83", "degc"}};
  std::string s;
  for (std::size_t i = 0; i < in.size();) {
    bool done = false;
    for (const auto& [from, to] : kUtf8) {
      if (static_cast<unsigned char>(in[i]) < 0x80) break;
      const std::string f = from;
      if (in.compare(i, f.size(), f) == 0) {
        s += to;
        i += f.size();
        done = true;
        break;
      }
    }
    if (done) continue;
    const auto c = static_cast<unsigned char>(in[i++]);
    if (c == 0xB2)
      s += '2';
    else if (c == 0xB3)
      s += '3';
    else if (c == 0xB5)
      s += 'u';
    else if (c == 0xB7)
      s += '*';
    else if (c == 0xB0)
      s += "deg";
    else if (c != ' ' && c != '\t' && c != '*' && c != '^' && c != '.')
      s += static_cast<char>(std::tolower(c));
  }
  return s;
}

std::optional<MeasurementUnit> acceleration(const std::string& s) {
  if (s == "g" || s == "gn") return MeasurementUnit{"g", Quantity::acceleration, 9.80665};
  if (s == "ms2" || s == "mps2") return MeasurementUnit{"m/s^2", Quantity::acceleration, 1.0};
  static const std::pair<const char*, double> kLength[] = {
      {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"in", 0.0254}, {"inch", 0.0254}, {"ft", 0.3048}};
  for (const auto& [length, metres] : kLength) {
    const std::string l = length;
    if (s.compare(0, l.size(), l) != 0) continue;
    const std::string per = s.substr(l.size());
    for (const char* form : {"/s2", "/sec2", "/s/s", "/sec/sec", "s-2", "sec-2", "/(s2)"})
      if (per == form) return MeasurementUnit{(l == "inch" ? "in" : l) + "/s^2", Quantity::acceleration, metres};
  }
  return std::nullopt;
}

std::optional<MeasurementUnit> time_unit(const std::string& s) {
  static const std::pair<const char*, std::pair<const char*, double>> kTime[] = {{"s", {"s", 1.0}},
                                                                                 {"sec", {"s", 1.0}},
                                                                                 {"secs", {"s", 1.0}},
                                                                                 {"second", {"s", 1.0}},
                                                                                 {"seconds", {"s", 1.0}},
                                                                                 {"ms", {"ms", 1e-3}},
                                                                                 {"msec", {"ms", 1e-3}},
                                                                                 {"millisecond", {"ms", 1e-3}},
                                                                                 {"milliseconds", {"ms", 1e-3}},
                                                                                 {"us", {"us", 1e-6}},
                                                                                 {"usec", {"us", 1e-6}},
                                                                                 {"microsecond", {"us", 1e-6}},
                                                                                 {"microseconds", {"us", 1e-6}},
                                                                                 {"ns", {"ns", 1e-9}},
                                                                                 {"nsec", {"ns", 1e-9}}};
  for (const auto& [spelling, unit] : kTime)
    if (s == spelling) return MeasurementUnit{unit.first, Quantity::time, unit.second};
  return std::nullopt;
}

// Units that are known to be no acceleration: a channel in one of them is not read as one in silence.
bool other_unit(const std::string& s) {
  for (const char* u : {"v",  "mv",  "uv",   "kv",   "n",   "kn",   "nm",   "pa",   "kpa",  "mpa", "bar",    "mbar",
                        "hz", "khz", "degc", "degf", "%",   "-",    "1",    "rpm",  "a",    "ma",  "m",      "cm",
                        "mm", "um",  "in",   "ft",   "m/s", "cm/s", "mm/s", "um/s", "in/s", "db",  "counts", "w"})
    if (s == u) return true;
  return false;
}

std::string strip_brackets(const std::string& text) {
  std::string t = trim(text);
  if (t.size() >= 2 && ((t.front() == '[' && t.back() == ']') || (t.front() == '(' && t.back() == ')') ||
                        (t.front() == '{' && t.back() == '}')))
    t = trim(t.substr(1, t.size() - 2));
  return t;
}

bool known_quantity(const std::optional<MeasurementUnit>& u) { return u && u->quantity != Quantity::other; }
}  // namespace

std::optional<MeasurementUnit> parse_measurement_unit(const std::string& text) {
  const std::string written = strip_brackets(text);
  if (written.empty()) return std::nullopt;
  const std::string s = normalise(written);
  if (auto a = acceleration(s)) return a;
  if (auto t = time_unit(s)) return t;
  if (other_unit(s)) return MeasurementUnit{written, Quantity::other, 1.0};
  return std::nullopt;
}

std::optional<MeasurementUnit> parse_psd_unit(const std::string& text) {
  std::string s = normalise(strip_brackets(text));
  const std::string per_hz = "/hz";
  if (s.size() <= per_hz.size() || s.compare(s.size() - per_hz.size(), per_hz.size(), per_hz) != 0) return std::nullopt;
  s.erase(s.size() - per_hz.size());
  if (s == "m2/s4" || s == "m2s-4") return MeasurementUnit{"(m/s^2)^2/Hz", Quantity::other, 1.0};
  if (s.empty() || s.back() != '2') return std::nullopt;
  s.pop_back();
  if (s.size() >= 2 && s.front() == '(' && s.back() == ')') s = s.substr(1, s.size() - 2);
  const auto a = acceleration(s);
  if (!a) return std::nullopt;
  return MeasurementUnit{a->text == "g" ? "g^2/Hz" : "(" + a->text + ")^2/Hz", Quantity::other, a->factor * a->factor};
}

NamedUnit unit_in_name(const std::string& name) {
  const std::string s = trim(name);
  NamedUnit n;
  n.base = s;
  // `Acc (g)`, `a [m/s²]`, `a/(m/s^2)`: the last bracket pair, if a name stands before it
  if (!s.empty() && (s.back() == ')' || s.back() == ']')) {
    const char close = s.back(), open = close == ')' ? '(' : '[';
    int depth = 0;
    std::size_t at = std::string::npos;
    for (std::size_t i = s.size(); i-- > 0;) {
      if (s[i] == close) ++depth;
      if (s[i] == open && --depth == 0) {
        at = i;
        break;
      }
    }
    std::string base = at == std::string::npos ? "" : trim(s.substr(0, at));
    if (!base.empty() && base.back() == '/') base = trim(base.substr(0, base.size() - 1));
    if (!base.empty()) {
      n.written = trim(s.substr(at + 1, s.size() - at - 2));
      n.unit = parse_measurement_unit(n.written);
      n.bracketed = true;
      if (n.unit) n.base = base;
      return n;
    }
  }
  // `time/ms`, `acc/g` (DIN 1313): the first '/' after which a unit follows
  for (std::size_t i = s.find('/'); i != std::string::npos; i = s.find('/', i + 1)) {
    const std::string base = trim(s.substr(0, i)), rest = trim(s.substr(i + 1));
    const auto u = parse_measurement_unit(rest);
    if (!base.empty() && known_quantity(u)) return {base, rest, u, true};
  }
  // `acc_g`, `time_ms`: acceleration and time units only (`pair_1`, `acc_mm` are names)
  const auto us = s.rfind('_');
  if (us != std::string::npos && us > 0) {
    const std::string rest = s.substr(us + 1);
    const auto u = rest.find_first_of("[]()") == std::string::npos ? parse_measurement_unit(rest) : std::nullopt;
    if (known_quantity(u)) return {trim(s.substr(0, us)), rest, u, false};
  }
  // `Acceleration m/s^2`, `Time ms`: a last word that cannot be a word
  const auto sp = s.find_last_of(" \t");
  if (sp != std::string::npos) {
    const std::string base = trim(s.substr(0, sp)), rest = s.substr(sp + 1);
    const auto u = parse_measurement_unit(rest);
    NamedUnit candidate{base, rest, u, true};
    if (u && ((u->quantity == Quantity::acceleration && rest.find_first_of("/^-") != std::string::npos) ||
              (u->quantity == Quantity::time && time_like_name(candidate, name))))
      return candidate;
  }
  return n;
}

bool units_row_cell(const std::string& cell) {
  const std::string c = trim(cell);
  if (c.empty()) return true;
  if (c.size() >= 2 && ((c.front() == '[' && c.back() == ']') || (c.front() == '(' && c.back() == ')'))) return true;
  return parse_measurement_unit(c).has_value();
}

bool time_like_name(const NamedUnit& n, const std::string& name) {
  std::string b;
  for (const char c : n.base)
    if (!std::isspace(static_cast<unsigned char>(c)))
      b += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // A bare capital T is a temperature or a tension as often as a time: only with a unit.
  if (trim(name) == "T") return false;
  for (const char* t : {"t", "time", "zeit", "temps", "tiempo", "tempo", "tijd", "tid"})
    if (b == t) return true;
  return false;
}

}  // namespace rollspec::io
