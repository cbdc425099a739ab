#include "src/fit/fit_goodness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernels/spectral/band_test_table.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::fit {

namespace {

constexpr double kLevel = 0.05;

std::string fitted_verdict(const spectral::BandTestResult& t, std::size_t p, std::size_t q, std::uint64_t K) {
  if (!t.defined)
    return "none (" + std::to_string(p) + " bands need K >= " + std::to_string(t.needed) +
           " realisations, the run has " + std::to_string(K) + ")";
  std::string buf;
  const char* verdict = t.p_value < kLevel ? "REJECTED" : "not rejected";
  const char* keys = q == 1 ? "key" : "keys";
  if (t.draws > 0)
    buf = io::formatted(
        "%s at level %g: p = %.3g (T2 = %.4g over the %g dimensions of the %zu bands that the %zu fitted "
        "%s cannot move, corrected for the search; law with the table's error by a parametric bootstrap "
        "of %zu draws; kernels/spectral D-27j, D-31)",
        verdict, kLevel, t.p_value, t.t2, t.dof1, p, q, keys, t.draws);
  else
    buf = io::formatted(
        "%s at level %g: p = %.3g (T2 = %.4g, F = %.4g on %g, %g dof: %zu bands less %zu fitted %s, "
        "corrected for the search; kernels/spectral D-27j)",
        verdict, kLevel, t.p_value, t.t2, t.f, t.dof1, t.dof2, p, q, keys);
  return buf;
}

}  // namespace

std::vector<FitPointReport> point_tests(FitModel& model, const FitInputs& in, const std::vector<double>& u,
                                        const std::vector<std::vector<double>>& jacobians) {
  const std::vector<io::BandLevels> runs = model.runs_at(u);
  const spectral::DrawUniforms uniform = [](std::uint64_t draw, double* x, std::size_t n) {
    rng::PhiloxStream(rng::kVerdictSeed, draw, rng::Stream::verdict_bootstrap).uniform_open(x, n);
  };
  std::vector<FitPointReport> out;
  for (std::size_t point = 0; point < runs.size(); ++point) {
    const io::BandLevels& b = runs[point];
    const std::vector<std::size_t>& band = model.band(point);
    const PointTable& t = model.table(point);
    const FitPoint& pt = in.points[point];
    FitPointReport r;
    r.measurement = pt.path, r.at = pt.at, r.question = t.question, r.bands = band.size(), r.records = pt.records;
    r.test = combined_test(b, band, model.measured_db(point), pt.records, kLevel, t.factor);
    const ChosenBands c = chosen_bands(b, band, model.measured_db(point));
    const std::vector<double> table = t.factor > 0.0 ? io::table_log_covariance(b, band) : std::vector<double>{};
    try {
      r.fitted = spectral::band_test_fitted(c.y.data(), c.mean.data(), c.cov.data(), band.size(), b.realisations,
                                            pt.records, jacobians[point].data(), in.vary.size(),
                                            {table.empty() ? nullptr : table.data(), b.table_dof, t.factor,
                                             b.table_independent_bands, 0, io::table_shrinkage(b, band)},
                                            uniform, compare::kBootstrapDraws);
      r.fitted_verdict = fitted_verdict(r.fitted, band.size(), in.vary.size(), b.realisations);
    } catch (const std::invalid_argument& e) {
      r.fitted_verdict = std::string("none (") + e.what() + ")";
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<std::vector<double>> crn_jacobians(FitModel& model, const std::vector<double>& u, double step) {
  const std::size_t n = u.size();
  std::vector<std::vector<double>> jac;
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<double> up = u, down = u;
    up[k] = std::min(1.0, u[k] + step), down[k] = std::max(0.0, u[k] - step);
    const auto a = model.log_means(up), z = model.log_means(down);
    if (jac.empty())
      for (const auto& m : a) jac.emplace_back(m.size() * n, 0.0);
    for (std::size_t point = 0; point < a.size(); ++point)
      for (std::size_t b = 0; b < a[point].size(); ++b)
        jac[point][b * n + k] = (a[point][b] - z[point][b]) / (up[k] - down[k]);
  }
  return jac;
}

}  // namespace rollspec::fit
