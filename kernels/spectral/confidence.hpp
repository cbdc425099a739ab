#pragma once
// Chi-square confidence interval of an averaged PSD estimate (theory D-16).
// An estimate P with nu equivalent degrees of freedom satisfies nu P / S ~ chi2(nu); the
// two-sided interval at level (1 - alpha) for the true S is
//   [ nu P / chi2_{1-alpha/2}(nu),  nu P / chi2_{alpha/2}(nu) ].
// K = 25 periodograms (nu = 50) give -1.55 / +1.89 dB at 95 %.
namespace rollspec::spectral {

struct IntervalFactors {
  double lower;  // multiply the estimate by this for the lower bound
  double upper;  // multiply the estimate by this for the upper bound
};

IntervalFactors chi_square_interval(double dof, double level = 0.95);

}  // namespace rollspec::spectral
