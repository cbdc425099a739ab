#pragma once
// The references' own linear algebra: a plain Gauss-Jordan inverse with partial pivoting, written out so that
// the reference paths (band_test_t2_reference, fit_response_surface_reference) share nothing with the Eigen
// factorisations of the paths they check.
#include <cstddef>
#include <vector>

namespace rollspec::spectral {

// [A | I] reduced to [I | A^-1] for the n x n row-major A; false (inv unfinished) where a pivot is exactly zero.
bool gauss_jordan_inverse(std::vector<double> a, std::size_t n, std::vector<double>& inv);

}  // namespace rollspec::spectral
