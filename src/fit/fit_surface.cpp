#include "src/fit/fit_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "kernels/spectral/band_test.hpp"
#include "kernels/spectral/response_surface.hpp"
#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::fit {

namespace {

using io::number_text;

constexpr int kMaxRounds = 5;
constexpr double kLackOfFitLevel = 0.01;  // a quadratic that fails its lack-of-fit test below this is not kept
constexpr double kBoxPerHalfWidth = 1.5;  // the next box reaches this many interval half-widths from the estimate
constexpr double kLocalBox = 3.0;         // a box wider than this many half-widths is not local yet
constexpr double kSmallestHalfWidth = 0.005;

// Runs per key in a round's grid: 9 points for one key, 16 for two, 27 for three (quadratic terms 3, 6, 10).
std::size_t grid_points(std::size_t keys) { return keys == 1 ? 9 : keys == 2 ? 4 : 3; }

std::vector<std::vector<double>> design(const std::vector<double>& lo, const std::vector<double>& hi) {
  const std::size_t n = lo.size(), g = grid_points(n);
  std::size_t total = 1;
  for (std::size_t i = 0; i < n; ++i) total *= g;
  std::vector<std::vector<double>> points;
  for (std::size_t k = 0; k < total; ++k) {
    std::vector<double> u(n);
    std::size_t rest = k;
    for (std::size_t i = 0; i < n; ++i, rest /= g)
      u[i] = lo[i] + (hi[i] - lo[i]) * static_cast<double>(rest % g) / static_cast<double>(g - 1);
    points.push_back(u);
  }
  return points;
}

struct Replicate {
  std::vector<double> u;
  std::vector<PointRun> runs;  // per point
};

// One round's smoothed likelihood over the box [lo, hi] from the replicates inside it (D-27i a, b).
struct Surrogate {
  std::vector<spectral::ResponseSurface> surface;  // per point
  std::vector<PointRun> pooled;                    // per point: the replicates' mean S and K
  std::vector<double> dof;                         // per point: the pooled S's degrees of freedom
  spectral::LackOfFit fit;

  double operator()(const FitModel& model, const std::vector<double>& u) const {
    double value = 0.0;
    for (std::size_t point = 0; point < surface.size(); ++point) {
      PointRun run = pooled[point];
      run.log_mean = surface[point].value(u);
      value -= model.point_log_likelihood(point, run, surface[point].leverage(u), dof[point]);
    }
    return value;
  }
};

Surrogate smooth(const std::vector<Replicate>& pool, const std::vector<double>& lo, const std::vector<double>& hi,
                 std::size_t points) {
  const std::size_t n = lo.size();
  std::vector<double> centre(n), half(n);
  for (std::size_t i = 0; i < n; ++i) centre[i] = 0.5 * (lo[i] + hi[i]), half[i] = 0.5 * (hi[i] - lo[i]);
  std::vector<const Replicate*> inside;
  for (const Replicate& r : pool) {
    bool in = true;
    for (std::size_t i = 0; i < n; ++i) in = in && r.u[i] >= lo[i] - 1e-12 && r.u[i] <= hi[i] + 1e-12;
    if (in) inside.push_back(&r);
  }
  Surrogate s;
  std::vector<spectral::LackOfFit> parts;
  for (std::size_t point = 0; point < points; ++point) {
    const std::size_t p = inside.front()->runs[point].log_mean.size();
    std::vector<double> u, y;
    PointRun pooled{{}, std::vector<double>(p * p, 0.0), inside.front()->runs[point].realisations};
    double dof = 0.0;
    for (const Replicate* r : inside) {
      const PointRun& run = r->runs[point];
      u.insert(u.end(), r->u.begin(), r->u.end());
      y.insert(y.end(), run.log_mean.begin(), run.log_mean.end());
      for (std::size_t k = 0; k < p * p; ++k) pooled.cov[k] += run.cov[k] / static_cast<double>(inside.size());
      dof += static_cast<double>(run.realisations) - 1.0;
    }
    s.surface.push_back(spectral::fit_response_surface(u, y, n, p, centre, half));
    // Omega: one run's covariance of its band logs, the pooled S scaled band by band to the log of a
    // K-realisation mean (D-26a's G with M -> K alone).
    std::vector<double> omega(p * p), g(p);
    const double K = static_cast<double>(pooled.realisations);
    for (std::size_t b = 0; b < p; ++b) {
      const double sb = pooled.cov[b * p + b];
      g[b] = sb > 0.0 ? std::sqrt(spectral::log_mean_variance(sb, K) / sb) : std::sqrt(1.0 / K);
    }
    for (std::size_t a = 0; a < p; ++a)
      for (std::size_t b = 0; b < p; ++b) omega[a * p + b] = g[a] * pooled.cov[a * p + b] * g[b];
    parts.push_back(spectral::lack_of_fit(s.surface.back(), omega));
    s.pooled.push_back(std::move(pooled));
    s.dof.push_back(dof);
  }
  s.fit = spectral::combined_lack_of_fit(parts);
  return s;
}

}  // namespace

std::pair<double, double> profile_interval(const spectral::BoxObjective& f, const std::vector<double>& best,
                                           double value, std::size_t j, int* evaluations) {
  const std::size_t n = best.size();
  std::vector<double> start;
  for (std::size_t i = 0; i < n; ++i)
    if (i != j) start.push_back(best[i]);
  spectral::ProfileContinuation profile(f, n, j, best[j], start, 0.05, kUnitTolerance, 40 * static_cast<int>(n - 1));
  const double lo =
      spectral::profile_end(std::ref(profile), best[j], value, 0.0, kProfileRise, kUnitTolerance, evaluations);
  const double hi =
      spectral::profile_end(std::ref(profile), best[j], value, 1.0, kProfileRise, kUnitTolerance, evaluations);
  return {lo, hi};
}

SurfaceFit surface_search(FitModel& model, const FitInputs& in) {
  const std::size_t n = in.vary.size(), points = in.points.size();
  std::vector<double> lo(n, 0.0), hi(n, 1.0);
  std::vector<Replicate> pool;
  std::uint64_t index = 0;
  SurfaceFit fit;
  for (int round = 1; round <= kMaxRounds; ++round) {
    for (const auto& u : design(lo, hi)) pool.push_back({u, model.replicate(u, index++)});
    const Surrogate s = smooth(pool, lo, hi, points);
    // The search and the profiles in the box's own unit coordinates v: u = lo + v (hi - lo).
    const auto to_u = [&](const std::vector<double>& v) {
      std::vector<double> u(n);
      for (std::size_t i = 0; i < n; ++i) u[i] = lo[i] + v[i] * (hi[i] - lo[i]);
      return u;
    };
    const spectral::BoxObjective f = [&](const std::vector<double>& v) {
      try {
        return s(model, to_u(v));
      } catch (const std::invalid_argument&) {
        return static_cast<double>(INFINITY);
      }
    };
    const spectral::BoxMinimum best = spectral::box_minimum(f, std::vector<double>(n, 0.5), 0.25, 1e-6, 400);
    if (!std::isfinite(best.value))
      throw data_error(in.points[0].path + ": the study has no power in a compared band anywhere the search went");
    fit.best = to_u(best.x), fit.value = best.value, fit.rounds = round, fit.lack_of_fit_p = s.fit.p_value;
    fit.lower.assign(n, 0.0), fit.upper.assign(n, 1.0);
    std::vector<double> next(n);
    bool edge = false, local = true;
    int extra = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const auto [a, b] = profile_interval(f, best.x, best.value, j, &extra);
      fit.lower[j] = lo[j] + a * (hi[j] - lo[j]), fit.upper[j] = lo[j] + b * (hi[j] - lo[j]);
      if (a == 0.0 && b == 1.0 && lo[j] == 0.0 && hi[j] == 1.0)
        throw data_error("--vary " + in.vary[j].key + ": the measurement cannot identify " + in.vary[j].key +
                         ": its profile likelihood stays within " + number_text(kProfileRise) +
                         " of the maximum over the whole range " + number_text(in.vary[j].lo) + " .. " +
                         number_text(in.vary[j].hi) +
                         " (a flat likelihood); fix it in the study, or fit it from bands where it matters");
      const bool cut = (a == 0.0 && lo[j] > 0.0) || (b == 1.0 && hi[j] < 1.0);  // by the box, not the range
      const double half = std::max(fit.best[j] - fit.lower[j], fit.upper[j] - fit.best[j]);
      edge = edge || cut;
      local = local && (hi[j] - lo[j]) / 2.0 <= kLocalBox * half;
      next[j] = std::max(kBoxPerHalfWidth * half, kSmallestHalfWidth);
      if (cut) next[j] = std::max(next[j], hi[j] - lo[j]);
    }
    fit.correlation = spectral::inverse_correlation(spectral::box_hessian(f, best.x, 0.02, &extra), n);  // scale-free
    fit.jacobians.clear();
    for (std::size_t point = 0; point < points; ++point) fit.jacobians.push_back(s.surface[point].gradient(fit.best));
    const bool quadratic = s.fit.p_value >= kLackOfFitLevel;
    if (!edge && local && quadratic) {
      fit.runs = static_cast<int>(pool.size());
      return fit;
    }
    if (!edge && local && !quadratic) {  // the interval fits in a box half as wide: try the quadratic there
      bool shrinks = true;
      for (std::size_t j = 0; j < n; ++j) {
        next[j] = (hi[j] - lo[j]) / 4.0;
        shrinks = shrinks && next[j] >= std::max(fit.best[j] - fit.lower[j], fit.upper[j] - fit.best[j]);
      }
      if (!shrinks) {
        const std::string buf = io::formatted(
            "a quadratic does not follow the band logs over the smallest box that holds the interval "
            "(lack of fit p = %.2g < %g, kernels/spectral D-27i)",
            s.fit.p_value, kLackOfFitLevel);
        fit.refused = buf;
        break;
      }
    }
    for (std::size_t j = 0; j < n; ++j)
      lo[j] = std::max(0.0, fit.best[j] - next[j]), hi[j] = std::min(1.0, fit.best[j] + next[j]);
    if (round == kMaxRounds)
      fit.refused = "the smoothed likelihood's interval did not settle inside a box a quadratic follows in " +
                    std::to_string(kMaxRounds) + " rounds (kernels/spectral D-27i)";
  }
  // No interval: the last round's estimate stands, with its surface's derivatives for the test at it.
  fit.lower.clear(), fit.upper.clear();
  fit.runs = static_cast<int>(pool.size());
  return fit;
}

}  // namespace rollspec::fit
