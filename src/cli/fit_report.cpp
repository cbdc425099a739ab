#include "src/cli/fit_report.hpp"

#include <cmath>
#include <cstdio>

#include "kernels/spectral/fit_search.hpp"
#include "src/fit/fit_json.hpp"
#include "src/fit/fit_model.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

using fit::kCoherenceLimit;
using fit::objective_text;

std::string fit_text(const FitReport& r) {
  std::string buf;
  std::string text;
  if (r.points.size() == 1)
    buf = io::formatted("fit over %zu bands, K = %llu realisations per run, M = %g measured records\n", r.bands,
                        static_cast<unsigned long long>(r.realisations), r.points[0].records);
  else
    buf = io::formatted("joint fit over %zu points, %zu bands in all, K = %llu realisations per run\n", r.points.size(),
                        r.bands, static_cast<unsigned long long>(r.realisations));
  text += buf;
  text += "objective: " + objective_text(r.objective) + "\n";
  buf = io::formatted("%-28s %14s %14s %14s\n", "key", "estimate", "95%_lower", "95%_upper");
  text += buf;
  for (const auto& p : r.parameters) {
    if (r.no_interval.empty())
      buf = io::formatted("%-28s %14.6g %14.6g%s %14.6g%s\n", p.key.c_str(), p.estimate, p.lower,
                          p.lower_at_range_end ? "*" : " ", p.upper, p.upper_at_range_end ? "*" : " ");
    else
      buf = io::formatted("%-28s %14.6g %14s  %14s\n", p.key.c_str(), p.estimate, "none", "none");
    text += buf;
  }
  if (!r.no_interval.empty()) text += "no_interval: " + r.no_interval + "\n";
  if (r.parameters.size() > 1) {
    text += "correlation:";
    if (r.correlation.empty()) text += " none (ln L is not curved like a maximum there)";
    const std::size_t n = r.parameters.size();
    for (std::size_t i = 0; i < n && !r.correlation.empty(); ++i) {
      text += "\n ";
      for (std::size_t j = 0; j < n; ++j) {
        const double c = r.correlation[i * n + j];
        text += " " + (std::isfinite(c) ? io::significant_text(c, 10) : std::string("null"));
      }
    }
    text += "\n";
  }
  for (const auto& p : r.parameters)
    if (r.no_interval.empty() && (p.lower_at_range_end || p.upper_at_range_end)) {
      text += "*: the interval reaches the end of the --vary range there (widen the range to see where it ends)\n";
      break;
    }
  for (std::size_t i = 0; i < r.points.size(); ++i)
    if (!r.points[i].question.empty())
      text += (r.points.size() > 1 ? "point " + std::to_string(i + 1) + " asks of: " : "question: ") +
              r.points[i].question + "\n";
  buf = io::formatted("log_likelihood: %.6g\n", r.log_likelihood);
  text += buf;
  if (r.points.size() > 1)
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const auto& p = r.points[i];
      buf = io::formatted("point %zu: %s at %s: %zu bands, M = %g: ", i + 1, p.measurement.c_str(),
                          p.at.empty() ? "the study's keys" : p.at.c_str(), p.bands, p.records);
      text += buf + p.fitted_verdict + "\n";
    }
  text += "goodness_of_fit: " + r.verdict + "\ngoodness_of_fit_uncorrected: " + r.verdict_uncorrected +
          " (compare's test of the run at the estimate, blind to the fitted keys)\nevaluations: " +
          std::to_string(r.evaluations) + "\n";
  if (r.reused > 0) text += "reused_from_journal: " + std::to_string(r.reused) + "\n";
  return text;
}

}  // namespace rollspec::cli
