#pragma once
// A quadratic response surface of a fit's band logs (kernels/spectral/README.md D-27i). Where common
// random numbers do not hold, runs at u_1 .. u_N of the fitted keys, each with its own seed, give band
// logs y_j = mu(u_j) + e_j, the e_j independent between runs with the covariance Omega of a
// K-realisation mean's logs. mu is estimated band by band by least squares on the quadratic basis
//   phi(x) = (1, x_1 .. x_n, x_i x_k for i <= k),   x = (u - centre) / half_width,
// every band on the same design Phi (N x q), so
//   mu_hat(u) = B^T phi(x),   Cov(mu_hat(u)) = h(u) Omega,   h(u) = phi^T (Phi^T Phi)^{-1} phi   (D-27i a)
// and, when the quadratic holds, the residuals' R = sum_j r_j^T Omega^{-1} r_j is chi^2 with
// p (N - q) degrees of freedom (the bands' errors share the design: a Kronecker structure)   (D-27i b).
#include <cstddef>
#include <vector>

namespace rollspec::spectral {

// q = (n + 1)(n + 2) / 2 terms for n keys.
std::size_t quadratic_terms(std::size_t keys);

// phi(x) into phi[0 .. q): 1, then x_i, then x_i x_k (i <= k, i outer).
void quadratic_basis(const double* x, std::size_t keys, double* phi);

struct ResponseSurface {
  std::size_t keys = 0, bands = 0, terms = 0, runs = 0;
  std::vector<double> centre, half_width;                            // of the box the design spans (keys)
  std::vector<double> coefficients;                                  // B: terms x bands, row-major
  std::vector<double> gram_inverse;                                  // (Phi^T Phi)^{-1}: terms x terms
  std::vector<double> residuals;                                     // runs x bands
  std::vector<double> value(const std::vector<double>& u) const;     // mu_hat(u), bands
  double leverage(const std::vector<double>& u) const;               // h(u)
  std::vector<double> gradient(const std::vector<double>& u) const;  // d mu_hat / d u: bands x keys, row-major
};

// Least squares of y (runs x bands, row-major: y[j * bands + b]) on the quadratic basis of the points
// u (runs x keys, row-major) in the box (centre, half_width). Throws std::invalid_argument when the
// design does not determine the quadratic (fewer runs than terms, or a singular design).
ResponseSurface fit_response_surface(const std::vector<double>& u, const std::vector<double>& y, std::size_t keys,
                                     std::size_t bands, const std::vector<double>& centre,
                                     const std::vector<double>& half_width);

// The same least squares by the normal equations and Gauss-Jordan elimination, for tests.
ResponseSurface fit_response_surface_reference(const std::vector<double>& u, const std::vector<double>& y,
                                               std::size_t keys, std::size_t bands, const std::vector<double>& centre,
                                               const std::vector<double>& half_width);

struct LackOfFit {
  double statistic = 0.0;  // R
  double dof = 0.0;        // p (N - q)
  double p_value = 1.0;    // P(chi^2_dof >= R); 1 without residual degrees of freedom
};

// D-27i b, with Omega (bands x bands, row-major) the covariance of one run's band logs. Throws
// std::invalid_argument when Omega is not positive definite.
LackOfFit lack_of_fit(const ResponseSurface& s, const std::vector<double>& omega);

// Independent surfaces' tests as one (several operating points): their statistics and dof summed.
LackOfFit combined_lack_of_fit(const std::vector<LackOfFit>& parts);

}  // namespace rollspec::spectral
