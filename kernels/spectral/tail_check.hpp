#pragma once
// Are K realisations enough for a band's interval? (kernels/spectral/README.md D-29.)
// The interval of D-21 is the union of a gamma law and a lognormal law. The skewness of ln x is
// zero under the lognormal law and negative under every gamma law, so a right-skewed ln x is a
// tail heavier than both, which the interval does not model. Cochran's rule for a normal-theory
// interval of a mean, K > 25 G1^2 (Cochran 1977, Sampling Techniques, sect. 2.15), applied to
// the skewness of ln x that the sample shows beyond two standard errors of a normal sample's,
// gives the K needed: K >= 25 (G1 - 2 se)^2.
#include <cstdint>

namespace rollspec::spectral {

struct TailCheck {
  double skewness = 0.0;        // G1 of ln x (adjusted Fisher-Pearson); 0 when undefined
  double standard_error = 0.0;  // of G1 for a normal sample of K
  std::uint64_t needed = 0;     // realisations Cochran's rule asks for (0: no evidence of a tail)
  bool defined = false;         // K >= 3 and ln x scatters
  bool enough(std::uint64_t realisations) const { return !defined || realisations >= needed; }
};

// From the sums over K realisations of y = ln x, y^2 and y^3 (raw power sums, as the ensemble
// driver keeps them).
TailCheck tail_check(std::uint64_t realisations, double sum, double sum_sq, double sum_cubes);

// The same from the K values of y themselves (two passes): the plain reference for the tests.
TailCheck tail_check_reference(const double* y, std::uint64_t realisations);

}  // namespace rollspec::spectral
