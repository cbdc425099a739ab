#pragma once
// The tests of a fit at its estimate (kernels/spectral D-27j): compare's combined test of the run there
// (D-26, with the table's error D-31 where the fit carries it), and the same corrected for the fitted
// keys, which have used up as many of the bands' dimensions as there are keys.
#include <vector>

#include "src/fit/fit_model.hpp"
#include "src/fit/fit_answer.hpp"

namespace rollspec::fit {

// Each point's tests at u, with J (bands x keys, row-major) its band logs' derivatives there.
std::vector<FitPointReport> point_tests(FitModel& model, const FitInputs& in, const std::vector<double>& u,
                                        const std::vector<std::vector<double>>& jacobians);

// d ln m / d u at u by differences of the study seed's runs over +-step (inside the unit box), per point:
// where common random numbers hold these are the model's own derivatives.
std::vector<std::vector<double>> crn_jacobians(FitModel& model, const std::vector<double>& u, double step);

}  // namespace rollspec::fit
