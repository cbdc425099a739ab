#pragma once
// The combined test over bands with a table term (kernels/spectral/README.md D-31): D-26's T^2 whose
// covariance adds c times the table's band-by-band covariance Sigma_T (D-30's jackknife, nu_T dof):
//   V = G S G + c Sigma_T,   T^2 = d^T V^{-1} d      (d, G, S as D-26a, b)
// c = 2 asks of a rig with another surface of this roughness (the model's table and the rig's own
// surface each deviate from the roughness's mean by Sigma_T), c = 0 of the very surface the table was
// built on (D-26 itself). With c > 0 the law of T^2 depends on S and Sigma_T, so its p-value comes
// from a parametric bootstrap: B draws of the estimates S* ~ W_p(S, K - 1) / (K - 1) and
// Sigma_T* ~ W_r(Sigma_T, nu_T) / nu_T (Bartlett, r = rank Sigma_T) and of d* ~ N(0, V), each
// giving T*^2 = d*^T V*^{-1} d* with V* from the draws as V from the estimates (D-31b);
// p = (1 + #{T*^2 >= T^2}) / (B + 1). With Sigma_T = 0 the bootstrap law is Hotelling's (pivotal).
// A full Sigma_T enters shrunk toward its diagonal (D-31e, TableTerm::shrinkage).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernels/spectral/band_test.hpp"

namespace rollspec::spectral {

// uniform(draw, u, n): fills u[0..n) with independent uniforms on (0, 1) for bootstrap draw `draw`
// (a counter-based stream: the draws do not depend on the order they are asked in).
using DrawUniforms = std::function<void(std::uint64_t draw, double* u, std::size_t n)>;

struct TableTerm {
  const double* covariance = nullptr;  // Sigma_T, p x p row-major, of the band logs (natural log squared)
  double dof = 0.0;                    // nu_T (> rank - 1)
  double factor = 2.0;                 // c
  bool independent = false;            // Sigma_T diagonal: each band's variance drawn alone, chi^2(nu_T) / nu_T
  // Independent bands only (D-31d): each band's variance is the mean of the raw estimates over the bands
  // within `smooth` of it (its neighbours among the p), in the observed term and in every draw alike.
  std::size_t smooth = 0;
  // A full Sigma_T only (D-31e): its correlations shrunk by lambda toward its diagonal, in the observed term
  // and in every draw alike (each draw's Sigma_T* drawn at Sigma_T's rank, then shrunk; lambda held).
  double shrinkage = 0.0;
};

// D-31d: the moving mean of v[0..p) over [b - w, b + w] (clipped at the ends), and the number of
// estimates each output averages.
std::vector<double> smoothed_variances(const std::vector<double>& v, std::size_t w,
                                       std::vector<std::size_t>* count = nullptr);

// D-31. Without a table term (factor 0, or no covariance) it is band_test (the F law). `draws`: B. `noise`: the
// logger noise's terms of the p bands (D-33c; null: none), in V and in every draw's V* (held at their estimates).
// `cv2`: the p bands' CV^2 of one realisation's band power (D-26d; null: e^{S_bb} - 1); a draw's is cv2 times
// S*_bb / S_bb, so G* moves with S*'s diagonal as G with S's. Throws std::invalid_argument as band_test does, and
// for a table covariance that is not symmetric positive semi-definite or nu_T <= rank - 1.
BandTestResult band_test_with_table(const double* measured_log, const double* mean, const double* covariance,
                                    std::size_t p, std::uint64_t realisations, double records, const TableTerm& table,
                                    const DrawUniforms& uniform, std::size_t draws, const BandNoise* noise = nullptr,
                                    const double* cv2 = nullptr);

// D-27j: the combined test of a fit, its search accounted for. The q fitted keys move the model's band
// logs along the columns of J (p x q, row-major: d ln m_b / d u_k at the estimate), so the part of d they
// can absorb is no evidence against the model: with C (p x p', p' = p - q) an orthonormal basis of the
// complement of J's columns,
//   T^2 = (C^T d)^T (C^T V C)^{-1} (C^T d),
// Hotelling's statistic in p' dimensions: F = (nu - p' + 1) / (nu p') T^2 ~ F(p', nu - p' + 1) (the test
// of a linear structure of the mean, Rao 1959), or, with a table term, D-31b's bootstrap with every draw
// projected the same way. q = 0 (or J null) is band_test_with_table itself. Throws as it does, and for
// q >= p or a J of rank below q.
BandTestResult band_test_fitted(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                                std::uint64_t realisations, double records, const double* jacobian, std::size_t q,
                                const TableTerm& table, const DrawUniforms& uniform, std::size_t draws);

// W_q(I, nu) by Bartlett's decomposition: A = L L^T, L lower triangular, L_ii^2 ~ chi^2(nu - i)
// (i = 0..q-1, by the inverse of the regularised gamma function from u[i]), L_ij ~ N(0, 1) below the
// diagonal (Box-Muller from the uniforms after the first q). Row-major q x q into a; it reads
// bartlett_uniforms(q) uniforms. Exposed for its test.
std::size_t bartlett_uniforms(std::size_t q);
void bartlett_wishart(std::size_t q, double nu, const double* u, double* a);

}  // namespace rollspec::spectral
