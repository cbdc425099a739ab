#include "src/cli/fit_report.hpp"

#include <cmath>
#include <cstdio>

#include "kernels/spectral/fit_search.hpp"

namespace rollspec::cli {

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// A JSON string: quotes and backslashes escaped, control characters (a path may hold them) as \u00XX.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

void combine_point_tests(FitReport& r) {
  if (r.points.size() == 1) {
    r.test_defined = r.points[0].test.result.defined;
    r.p_value = r.points[0].test.result.p_value;
    r.verdict = r.points[0].test.verdict;
    return;
  }
  std::vector<double> p;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    if (!r.points[i].test.result.defined) {
      r.verdict = "none (point " + std::to_string(i + 1) + ": " + r.points[i].test.verdict + ")";
      return;
    }
    p.push_back(r.points[i].test.result.p_value);
  }
  r.test_defined = true;
  r.p_value = spectral::fisher_combined_p(p);
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s at level 0.05: p = %.3g (Fisher's combination of the %zu points' tests)",
                r.p_value < 0.05 ? "REJECTED" : "not rejected", r.p_value, p.size());
  r.verdict = buf;
}

std::string fit_text(const FitReport& r) {
  char buf[320];
  std::string text;
  if (r.points.size() == 1)
    std::snprintf(buf, sizeof buf, "fit over %zu bands, K = %llu realisations per run, M = %g measured records\n",
                  r.bands, static_cast<unsigned long long>(r.realisations), r.points[0].records);
  else
    std::snprintf(buf, sizeof buf, "joint fit over %zu points, %zu bands in all, K = %llu realisations per run\n",
                  r.points.size(), r.bands, static_cast<unsigned long long>(r.realisations));
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
  if (r.points.size() > 1)
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const auto& p = r.points[i];
      std::snprintf(buf, sizeof buf, "point %zu: %s at %s: %zu bands, M = %g: ", i + 1, p.measurement.c_str(),
                    p.at.empty() ? "the study's keys" : p.at.c_str(), p.bands, p.records);
      text += buf + p.test.verdict + "\n";
    }
  text += "goodness_of_fit: " + r.verdict + "\nevaluations: " + std::to_string(r.evaluations) + "\n";
  if (r.reused > 0) text += "reused_from_journal: " + std::to_string(r.reused) + "\n";
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
          ",\n  \"p_value\": " + (r.test_defined ? number(r.p_value) : "null") +
          ",\n  \"goodness_of_fit\": " + quoted(r.verdict) + ",\n  \"points\": [";
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const auto& p = r.points[i];
    text += std::string(i ? "," : "") + "\n    {\"measurement\": " + quoted(p.measurement) +
            ", \"at\": " + quoted(p.at) + ", \"bands\": " + std::to_string(p.bands) +
            ", \"measured_averages\": " + number(p.records) +
            ", \"p_value\": " + (p.test.result.defined ? number(p.test.result.p_value) : "null") +
            ", \"goodness_of_fit\": " + quoted(p.test.verdict) + "}";
  }
  text += "\n  ],\n  \"bands\": " + std::to_string(r.bands) +
          ",\n  \"realisations\": " + std::to_string(r.realisations) +
          ",\n  \"measured_averages\": " + (r.points.size() == 1 ? number(r.points[0].records) : "null") +
          ",\n  \"evaluations\": " + std::to_string(r.evaluations) +
          ",\n  \"reused_from_journal\": " + std::to_string(r.reused) + "\n}\n";
  return text;
}

}  // namespace rollspec::cli
