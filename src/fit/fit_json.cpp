#include "src/fit/fit_json.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "src/fit/fit_model.hpp"
#include "src/io/json_number.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::fit {

using io::json_number;

std::string objective_text(const FitObjective& o) {
  std::string buf;
  if (o.common_random_numbers)
    buf = io::formatted(
        "common random numbers hold (the band logs' second difference over a step of %g of each range is "
        "%.2g %% of independent runs'): ln L of the study's seed, profile-likelihood intervals "
        "(kernels/spectral D-27d)",
        o.step, 100.0 * o.incoherent_share);
  else
    buf = io::formatted(
        "common random numbers do not hold (the band logs' second difference over a step of %g of each "
        "range is %.3g %% of independent runs', above %g %%): ln L smoothed by a quadratic response "
        "surface of %d runs with seeds of their own, %d rounds, lack of fit p = %.2g (kernels/spectral "
        "D-27i)",
        o.step, 100.0 * o.incoherent_share, 100.0 * kCoherenceLimit, o.surface_runs, o.rounds, o.lack_of_fit_p);
  return buf;
}

std::string fit_json(const FitReport& r) {
  using json = nlohmann::ordered_json;
  const std::size_t n = r.parameters.size();
  json parameters = json::object();
  for (const auto& p : r.parameters) {
    const bool interval = r.no_interval.empty();
    parameters[p.key] = {
        {"estimate", json_number(p.estimate)},
        {"interval", interval ? json::array({json_number(p.lower), json_number(p.upper)}) : json(nullptr)},
        {"interval_at_range_end",
         interval ? json::array({p.lower_at_range_end, p.upper_at_range_end}) : json(nullptr)}};
  }
  json correlation = nullptr;
  if (!r.correlation.empty()) {
    correlation = json::array();
    for (std::size_t i = 0; i < n; ++i) {
      json row = json::array();
      for (std::size_t j = 0; j < n; ++j) row.push_back(json_number(r.correlation[i * n + j]));
      correlation.push_back(row);
    }
  }
  const FitObjective& o = r.objective;
  const json objective = {
      {"common_random_numbers", o.common_random_numbers},
      {"incoherent_share", json_number(o.incoherent_share)},
      {"step", json_number(o.step)},
      {"incoherent_limit", json_number(kCoherenceLimit)},
      {"method", o.common_random_numbers ? "profile likelihood of the study's seed" : "quadratic response surface"},
      {"surface_runs", o.surface_runs},
      {"rounds", o.rounds},
      {"lack_of_fit_p", o.common_random_numbers ? json(nullptr) : json_number(o.lack_of_fit_p)},
      {"text", objective_text(o)}};
  json points = json::array();
  for (const auto& p : r.points)
    points.push_back(
        {{"measurement", p.measurement},
         {"at", p.at},
         {"bands", p.bands},
         {"measured_averages", json_number(p.records)},
         {"p_value", p.fitted.defined ? json_number(p.fitted.p_value) : json(nullptr)},
         {"goodness_of_fit", p.fitted_verdict},
         {"p_value_uncorrected", p.test.result.defined ? json_number(p.test.result.p_value) : json(nullptr)},
         {"goodness_of_fit_uncorrected", p.test.verdict},
         {"question", p.question.empty() ? json(nullptr) : json(p.question)}});
  const json out = {{"parameters", parameters},
                    {"correlation", correlation},
                    {"confidence_level", 0.95},
                    {"no_interval", r.no_interval.empty() ? json(nullptr) : json(r.no_interval)},
                    {"objective", objective},
                    {"log_likelihood", json_number(r.log_likelihood)},
                    {"p_value", r.test_defined ? json_number(r.p_value) : json(nullptr)},
                    {"goodness_of_fit", r.verdict},
                    {"p_value_uncorrected", r.uncorrected_defined ? json_number(r.p_value_uncorrected) : json(nullptr)},
                    {"goodness_of_fit_uncorrected", r.verdict_uncorrected},
                    {"points", points},
                    {"bands", r.bands},
                    {"realisations", r.realisations},
                    {"measured_averages", r.points.size() == 1 ? json_number(r.points[0].records) : json(nullptr)},
                    {"evaluations", r.evaluations},
                    {"reused_from_journal", r.reused}};
  // Text from the user (a measurement's path, a key) may hold bytes that are not UTF-8: replaced, not refused.
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace rollspec::fit
