#include "src/fit/fit_search.hpp"

#include <cmath>
#include <vector>

#include "kernels/spectral/fit_search.hpp"
#include "src/error.hpp"
#include "src/fit/fit_goodness.hpp"
#include "src/fit/fit_surface.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::fit {

namespace {

using io::number_text;

// Where common random numbers hold: Nelder-Mead on ln L of the study's seed, the profile-likelihood
// intervals and the Hessian's correlation (kernels/spectral D-27c-e).
void crn_search(FitModel& model, const FitInputs& in, FitReport& report, std::vector<double>& best_u,
                std::vector<std::vector<double>>& jacobians) {
  const std::size_t n = in.vary.size();
  const spectral::BoxObjective f = [&](const std::vector<double>& u) { return model.negative_log_likelihood(u); };
  const spectral::BoxMinimum best =
      spectral::box_minimum(f, std::vector<double>(n, 0.5), 0.25, 1e-4, 150 * static_cast<int>(n));
  if (!std::isfinite(best.value))
    throw data_error(in.points[0].path + ": the study has no power in a compared band anywhere the search went");
  int extra = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const auto [lo, hi] = profile_interval(f, best.x, best.value, j, &extra);
    const VaryRange& v = in.vary[j];
    if (lo == 0.0 && hi == 1.0)
      throw data_error("--vary " + v.key + ": the measurement cannot identify " + v.key +
                       ": its profile likelihood stays within " + number_text(kProfileRise) +
                       " of the maximum over the whole range " + number_text(v.lo) + " .. " + number_text(v.hi) +
                       " (a flat likelihood); fix it in the study, or fit it from bands where it matters");
    report.parameters.push_back({v.key, v.value(best.x[j]), v.value(lo), v.value(hi), lo == 0.0, hi == 1.0});
  }
  report.correlation = spectral::inverse_correlation(spectral::box_hessian(f, best.x, 0.02, &extra), n);
  report.log_likelihood = -best.value;
  best_u = best.x;
  jacobians = crn_jacobians(model, best.x, kCoherenceStep);
}

// Where they do not: the response surface of replicates with seeds of their own (D-27i).
void smoothed_search(FitModel& model, const FitInputs& in, FitReport& report, std::vector<double>& best_u,
                     std::vector<std::vector<double>>& jacobians) {
  const SurfaceFit s = surface_search(model, in);
  for (std::size_t j = 0; j < in.vary.size(); ++j) {
    const VaryRange& v = in.vary[j];
    const bool interval = s.refused.empty();
    report.parameters.push_back({v.key, v.value(s.best[j]), interval ? v.value(s.lower[j]) : NAN,
                                 interval ? v.value(s.upper[j]) : NAN, interval && s.lower[j] == 0.0,
                                 interval && s.upper[j] == 1.0});
  }
  if (!s.refused.empty())
    report.no_interval = "the estimate is the smoothed likelihood's maximum, without an interval: " + s.refused;
  report.correlation = s.correlation;
  report.log_likelihood = -s.value;
  report.objective.surface_runs = s.runs, report.objective.rounds = s.rounds;
  report.objective.lack_of_fit_p = s.lack_of_fit_p;
  best_u = s.best;
  jacobians = s.jacobians;
}

}  // namespace

FitReport fit_search(FitModel& model, const FitInputs& in) {
  FitReport report;
  const Coherence c = model.probe(std::vector<double>(in.vary.size(), 0.5), kCoherenceStep);
  report.objective.step = c.step, report.objective.incoherent_share = c.incoherent_share;
  report.objective.common_random_numbers = c.holds;
  std::vector<double> best;
  std::vector<std::vector<double>> jacobians;
  if (c.holds)
    crn_search(model, in, report, best, jacobians);
  else
    smoothed_search(model, in, report, best, jacobians);
  report.points = point_tests(model, in, best, jacobians);
  combine_point_tests(report);
  report.evaluations = model.runs();
  report.reused = model.reused();
  report.bands = model.bands();
  report.realisations = model.realisations();
  return report;
}

}  // namespace rollspec::fit
