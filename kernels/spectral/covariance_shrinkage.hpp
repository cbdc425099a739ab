#pragma once
// Shrinking a table's band-by-band covariance toward its diagonal (kernels/spectral/README.md D-31e).
// A jackknife over N units (N - 1 = 5 .. 9 degrees of freedom) estimates a p x p covariance of p ~ 20 bands:
// its correlations are noisy, and the test's V^{-1} trusts them in every direction. Schaefer & Strimmer
// (2005, Stat. Appl. Genet. Mol. Biol. 4:32, target D "diagonal, unequal variance") shrink the
// correlations by the intensity their own sampling variance asks for:
//   (a) Sigma_lambda = (1 - lambda) Sigma + lambda diag(Sigma)
//   (b) lambda* = sum_{k != l} Var^(r_kl) / sum_{k != l} r_kl^2, clipped to [0, 1], where x_ik is unit i's
//       value of band k standardised over the units (mean 0, sample variance 1), w_ikl = x_ik x_il,
//       r_kl = n/(n - 1) mean_i w_ikl (the sample correlation) and
//       Var^(r_kl) = n/(n - 1)^3 sum_i (w_ikl - mean_i w_ikl)^2.
// The variances (the diagonal) are kept; only the correlations shrink. A band that does not vary over the
// units has no correlation to estimate and is left out of both sums.
#include <cstddef>

namespace rollspec::spectral {

// (b) from x[i * p + k] (unit i of n, band k of p), by matrix products over the standardised values.
// 1 when no pair of bands has a correlation to estimate (p < 2, n < 3, or every band constant but one);
// throws std::invalid_argument for a value that is not finite.
double shrinkage_intensity(const double* x, std::size_t n, std::size_t p);

// (b) pair by pair in plain loops: the reference the tests compare shrinkage_intensity with.
double shrinkage_intensity_reference(const double* x, std::size_t n, std::size_t p);

// (a) in place on a row-major p x p covariance.
void shrink_toward_diagonal(double* covariance, std::size_t p, double lambda);

}  // namespace rollspec::spectral
