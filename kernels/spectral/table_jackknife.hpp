#pragma once
// A table's own sampling error in an interval by a leave-one-surface-out jackknife
// (kernels/spectral/README.md D-30). The ensemble is run with the full table of N surfaces and
// with each of its N leave-one-out sub-tables, the same realisation streams in every run; theta_i
// is a log level (dB) with sub-table i.
//   (a) V_J = (N - 1)/N sum_i (theta_i - mean theta)^2
//   (b) s^2 = s_w^2 + V_J, s_w = h / t_{K-1}(level), nu = s^4 / (s_w^4/(K - 1) + V_J^2/nu_T),
//       widened half width t_nu(level) s; nu_T = N - 1 for independent surfaces or strips (D-30d:
//       fewer for overlapping Welch segments)
//   (c) the part of (a) that is the N ensembles' own sampling noise (reported beside (a)): with x_ir
//       realisation r's value (linear: a bin's PSD, a band's average) under sub-table i, m_i its
//       mean over K realisations, d_ir = x_ir - (1/N) sum_j x_jr (the same realisation's mean over
//       the N runs), q = sum_r sum_i d_ir^2 and s_i^2 the variance of d_ir over r,
//       sum_i s_i^2 = (q - K sum_i (m_i - mean m)^2)/(K - 1),
//       noise = (10/ln 10)^2 (N - 1)/N sum_i s_i^2 / (K mean m^2)   (dB^2, to first order)
//       V_J - noise is an unbiased estimate of the table's term alone, but too noisy to widen by
// (b) is applied to each side of an interval on its own (D-21's interval is not symmetric).
#include <cstddef>
#include <cstdint>

namespace rollspec::spectral {

// (a) from the N leave-one-out values, two passes (mean, then squared deviations). NaN when a
// value is not finite (a bin without power in some run); 0 for N < 2.
double jackknife_variance(const double* theta, std::size_t n);

// (a) by pairs, sum_i (theta_i - mean)^2 = (1/N) sum_{i<j} (theta_i - theta_j)^2: the plain
// reference for the tests (no mean is formed).
double jackknife_variance_reference(const double* theta, std::size_t n);

// (c) from the sums a combined run keeps: q, and the N runs' means m[0..n) over K realisations.
// NaN when the mean of m is not positive or K < 2.
double paired_noise_variance(double q, const double* m, std::size_t n, std::uint64_t K);

// (c) directly from the paired values x[i * K + r] (run i, realisation r), two passes per run:
// the plain reference for the tests.
double paired_noise_variance_reference(const double* x, std::size_t n, std::uint64_t K);

struct WidenedHalfWidth {
  double half_width = 0.0;  // t_nu s, in the units of h
  double dof = 0.0;         // nu (Welch-Satterthwaite)
};

// (b): a half width h of the realisations' interval at `level` from K realisations, widened by a
// jackknife variance v of table_dof degrees of freedom (nu_T: N - 1 over N independent surfaces). h
// unchanged (dof K - 1) when v is 0, not finite, or h is not a finite positive width (no interval).
WidenedHalfWidth widen_half_width(double h, std::uint64_t realisations, double v, double table_dof, double level);

}  // namespace rollspec::spectral
