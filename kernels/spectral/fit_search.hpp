#pragma once
// Derivative-free search for the fit of a few study parameters (theory D-27): Nelder-Mead on the
// unit box [0, 1]^n (the command maps each parameter's range, linear or logarithmic, onto [0, 1]),
// the profile interval of one coordinate, and the Hessian by central differences. A dense grid
// search is the plain reference the tests compare the simplex with.
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace rollspec::spectral {

// The function minimised (a negative log-likelihood) at a point of the unit box.
using BoxObjective = std::function<double(const std::vector<double>&)>;

struct BoxMinimum {
  std::vector<double> x;  // in [0, 1]^n
  double value = 0.0;
  int evaluations = 0;
};

// Nelder-Mead (reflection 1, expansion 2, contraction 1/2, shrink 1/2) from `start` with an initial
// simplex of edge `step`; points outside the box are clamped onto it. Stops when the simplex's
// largest edge is below `tolerance` and its values span less than `tolerance`, or after
// max_evaluations.
BoxMinimum box_minimum(const BoxObjective& f, const std::vector<double>& start, double step, double tolerance,
                       int max_evaluations);

// Reference: the best of a grid of `points` per coordinate (points >= 2, ends included).
BoxMinimum box_minimum_grid_reference(const BoxObjective& f, std::size_t n, int points);

// One end of the profile interval of coordinate j: `profile(t)` is the objective minimised over the
// other coordinates with coordinate j held at t. Starting from the minimum at x_j = t0 (value f0),
// finds t between t0 and `end` (0 or 1) where profile(t) - f0 = rise (regula falsi on the square root of
// the rise, to `tolerance` in t or 1e-3 of sqrt(rise));
// returns `end` when profile(end) - f0 <= rise (the interval reaches the end of the range).
double profile_end(const std::function<double(double)>& profile, double t0, double f0, double end, double rise,
                   double tolerance, int* evaluations);

// The profile of f in coordinate j: profile(t) = f minimised over the other coordinates with x_j = t
// (Nelder-Mead, initial step `step`). Each search starts from the optimum of the nearest t already
// solved, beginning with (t0, others0), the fit's optimum: continuation along the profile. A start
// carried over from the previous call instead (regula falsi jumps between a bracket's ends, one of
// them the range's end) can sit in another basin and make the profile rise falsely.
class ProfileContinuation {
 public:
  ProfileContinuation(BoxObjective f, std::size_t n, std::size_t j, double t0, const std::vector<double>& others0,
                      double step, double tolerance, int max_evaluations);
  double operator()(double t);

 private:
  BoxObjective f_;
  std::size_t n_, j_;
  double step_, tolerance_;
  int max_evaluations_;
  std::vector<std::pair<double, std::vector<double>>> solved_;  // t, the other coordinates' optimum
};

// Hessian (n x n, row-major) of f at x by central differences of step h, the stencil moved inside
// the box where x is nearer than h to an edge.
std::vector<double> box_hessian(const BoxObjective& f, const std::vector<double>& x, double h, int* evaluations);

// Correlation matrix of the inverse of a symmetric positive definite n x n matrix (row-major);
// empty when it is not positive definite.
std::vector<double> inverse_correlation(const std::vector<double>& h, std::size_t n);

// Fisher's combination of k independent tests' p-values: P(chi2_2k >= -2 sum ln p_i), in closed form
// (the chi2 survival function of even degrees of freedom, a Poisson sum). 1 for k = 0; 0 if a p is 0.
double fisher_combined_p(const std::vector<double>& p);

}  // namespace rollspec::spectral
