#include "src/cli/fit_report.hpp"

#include <cmath>
#include <cstdio>

namespace rollspec::cli {

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Keys are section.key names (letters, digits, _ and .): no escaping needed beyond quotes.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string fit_text(const FitReport& r) {
  char buf[320];
  std::string text;
  std::snprintf(buf, sizeof buf, "fit over %zu bands, K = %llu realisations per run, M = %g measured records\n",
                r.bands, static_cast<unsigned long long>(r.realisations), r.records);
  text += buf;
  std::snprintf(buf, sizeof buf, "%-28s %14s %14s %14s\n", "key", "estimate", "95%_lower", "95%_upper");
  text += buf;
  for (const auto& p : r.parameters) {
    std::snprintf(buf, sizeof buf, "%-28s %14.6g %14.6g%s %14.6g%s\n", p.key.c_str(), p.estimate, p.lower,
                  p.lower_at_range_end ? "*" : " ", p.upper, p.upper_at_range_end ? "*" : " ");
    text += buf;
  }
  if (r.parameters.size() > 1) {
    text += "correlation:";
    if (r.correlation.empty()) text += " none (ln L is not curved like a maximum there)";
    const std::size_t n = r.parameters.size();
    for (std::size_t i = 0; i < n && !r.correlation.empty(); ++i) {
      text += "\n ";
      for (std::size_t j = 0; j < n; ++j) text += " " + number(r.correlation[i * n + j]);
    }
    text += "\n";
  }
  for (const auto& p : r.parameters)
    if (p.lower_at_range_end || p.upper_at_range_end) {
      text += "*: the interval reaches the end of the --vary range there (widen the range to see where it ends)\n";
      break;
    }
  std::snprintf(buf, sizeof buf, "log_likelihood: %.6g\n", r.log_likelihood);
  text += buf;
  text += "goodness_of_fit: " + r.test.verdict + "\nevaluations: " + std::to_string(r.evaluations) + "\n";
  return text;
}

std::string fit_json(const FitReport& r) {
  const std::size_t n = r.parameters.size();
  std::string text = "{\n  \"parameters\": {\n";
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = r.parameters[i];
    text += "    " + quoted(p.key) + ": {\"estimate\": " + number(p.estimate) + ", \"interval\": [" + number(p.lower) +
            ", " + number(p.upper) + "], \"interval_at_range_end\": [" + (p.lower_at_range_end ? "true" : "false") +
            ", " + (p.upper_at_range_end ? "true" : "false") + "]}" + (i + 1 < n ? ",\n" : "\n");
  }
  text += "  },\n  \"correlation\": ";
  if (r.correlation.empty())
    text += "null";
  else {
    text += "[";
    for (std::size_t i = 0; i < n; ++i) {
      text += i ? ", [" : "[";
      for (std::size_t j = 0; j < n; ++j) text += (j ? ", " : "") + number(r.correlation[i * n + j]);
      text += "]";
    }
    text += "]";
  }
  text += ",\n  \"confidence_level\": 0.95,\n  \"log_likelihood\": " + number(r.log_likelihood) +
          ",\n  \"p_value\": " + (r.test.result.defined ? number(r.test.result.p_value) : "null") +
          ",\n  \"goodness_of_fit\": " + quoted(r.test.verdict) + ",\n  \"bands\": " + std::to_string(r.bands) +
          ",\n  \"realisations\": " + std::to_string(r.realisations) +
          ",\n  \"measured_averages\": " + number(r.records) +
          ",\n  \"evaluations\": " + std::to_string(r.evaluations) + "\n}\n";
  return text;
}

}  // namespace rollspec::cli
