#pragma once
// Text as messages and tables print it, all through `formatted` (printf's format, into a string of whatever
// length it takes: no fixed buffer cuts a long message short). Numbers through significant_text ("%.*g"):
// number_text: six significant digits ("%.6g"), nan and inf spelled out; four_digits and three_digits:
// "%.4g", "%.3g"; exact_text: "%.17g", every bit of a double (the input texts that cached tables hash);
// si_text and length_text: SI-prefixed, six digits ("156.25 nm").
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <utility>

namespace rollspec::io {

// printf's format expanded into a string: the one formatter of the engine's text.
#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
inline std::string
formatted(const char* format, ...) {
  std::va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

// v with `digits` significant digits (1 to 17), as printf's %.*g prints it: the one number formatter.
inline std::string significant_text(double v, int digits) { return formatted("%.*g", digits, v); }

inline std::string number_text(double v) { return significant_text(v, 6); }
inline std::string four_digits(double v) { return significant_text(v, 4); }
inline std::string three_digits(double v) { return significant_text(v, 3); }
inline std::string exact_text(double v) { return significant_text(v, 17); }

// A quantity with an SI prefix and six significant digits (or `digits`), for lengths far from 1 m:
// si_text(1.5625e-7, "m") = "156.25 nm", si_text(0.0086722, "m") = "8.6722 mm" (ASCII "u" for micro).
inline std::string si_text(double v, const std::string& unit, int digits = 6) {
  static const std::pair<double, const char*> prefixes[] = {{1e3, "k"},  {1.0, ""},    {1e-3, "m"}, {1e-6, "u"},
                                                            {1e-9, "n"}, {1e-12, "p"}, {1e-15, "f"}};
  const double a = std::fabs(v);
  std::pair<double, const char*> p{1.0, ""};  // zero, inf and nan without a prefix
  if (a > 0.0 && std::isfinite(a)) {
    p = prefixes[6];
    for (const auto& q : prefixes)
      if (a >= q.first * (1.0 - 5e-11)) {  // 0.99999999999 mm prints as 1 mm
        p = q;
        break;
      }
  }
  return significant_text(v / p.first, digits) + " " + p.second + unit;
}

inline std::string length_text(double metres, int digits = 6) { return si_text(metres, "m", digits); }

// A count with its noun, singular for one: "1 realisation", "3 realisations" (nouns with a plain -s plural).
inline std::string counted(unsigned long long n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace rollspec::io
