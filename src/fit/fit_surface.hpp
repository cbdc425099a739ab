#pragma once
// rollspec fit where common random numbers do not hold (kernels/spectral D-27i): runs with seeds of
// their own over a box of the keys, each point's band logs smoothed by a quadratic response surface,
// ln L of the surface maximised and its profile intervals read, the box moved onto the interval and
// the design run again until the interval lies inside a box the quadratic follows (or the fit says
// why it gives no interval).
#include <string>
#include <utility>
#include <vector>

#include "kernels/spectral/fit_search.hpp"
#include "src/fit/fit_model.hpp"

namespace rollspec::fit {

// chi2_1(0.95) / 2: the rise of -ln L that bounds a 95 % profile-likelihood interval.
constexpr double kProfileRise = 3.841458820694124 / 2.0;
constexpr double kUnitTolerance = 1e-3;  // of the interval ends, in the unit box

// The 95 % profile-likelihood interval of coordinate j of f on the unit box (D-27d), from its minimum
// `best` of value `value`: its ends, 0 or 1 where it reaches the box's end.
std::pair<double, double> profile_interval(const spectral::BoxObjective& f, const std::vector<double>& best,
                                           double value, std::size_t j, int* evaluations);

struct SurfaceFit {
  std::vector<double> best;                    // u
  double value = 0.0;                          // -ln L of the surface there
  std::vector<double> lower, upper;            // u; empty with `refused`
  std::string refused;                         // non-empty: why there is no interval
  std::vector<double> correlation;             // keys x keys (empty: not a maximum)
  std::vector<std::vector<double>> jacobians;  // per point: d ln m / d u at best, bands x keys
  int runs = 0, rounds = 0;                    // runs: the replicates smoothed (run, or read from a journal)
  double lack_of_fit_p = 1.0;
};

// D-27i. Throws data_error when a key cannot be identified (its interval spans its whole range) or the
// model has no power in a band anywhere.
SurfaceFit surface_search(FitModel& model, const FitInputs& in);

}  // namespace rollspec::fit
