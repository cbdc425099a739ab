#pragma once
// rollspec fit's search (kernels/spectral D-27): the start's probe decides how ln L is read (common
// random numbers, or the smoothed surface of D-27i); then the estimate, its intervals and the tests at
// the best fit, as a typed answer (fit_answer.hpp).
#include "src/fit/fit_answer.hpp"
#include "src/fit/fit_model.hpp"

namespace rollspec::fit {

FitReport fit_search(FitModel& model, const FitInputs& in);

}  // namespace rollspec::fit
