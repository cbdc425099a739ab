#pragma once
// One level offset between a model and a measurement over the bands where they are compared (theory
// D-34): the weighted least-squares estimate of a constant c in d = c 1 + e, e ~ N(0, V), V = V_S + V_T
// (D-26a's G S G and D-31's table term), each band weighted by its own variance, and the estimate's
// variance from the whole V (bands correlate), with its Welch-Satterthwaite dof:
//   w_b = (1 / V_bb) / sum_c (1 / V_cc),  c = w^T d,  var c = w^T V w = w^T V_S w + w^T V_T w,
//   nu = (w^T V_S w + w^T V_T w)^2 / ((w^T V_S w)^2 / nu_S + (w^T V_T w)^2 / nu_T).
// Not generalised least squares: V^{-1} from K realisations is noisy off its diagonal (its smallest
// eigenvalues are the most underestimated), and weights from it chase that noise; diagonal weights stay
// unbiased and lose little where the bands are weakly correlated.
// A gain error (a unit, a mass, a sensitivity) moves every band by c; what is left, d - c 1, is shape.
#include <cstddef>

namespace rollspec::spectral {

struct LevelOffset {
  double estimate = 0.0;            // c, in the units of d
  double variance = 0.0;            // var c
  double dof = 0.0;                 // nu
  double lower = 0.0, upper = 0.0;  // c -+ t_{nu, (1 + level)/2} sqrt(var c)
};

// d: p deviations; v_s, v_t: p x p row-major (v_t may be null: no table term); nu_s, nu_t: their dof.
// Throws std::invalid_argument when V is not positive definite or p = 0.
LevelOffset level_offset(const double* d, const double* v_s, const double* v_t, std::size_t p, double nu_s, double nu_t,
                         double level);

// The same written out with an explicit inverse (Gauss-Jordan), for the tests.
LevelOffset level_offset_reference(const double* d, const double* v_s, const double* v_t, std::size_t p, double nu_s,
                                   double nu_t, double level);

}  // namespace rollspec::spectral
