// LU factorisation with partial pivoting of a banded matrix (kl sub-, ku super-diagonals), for
// the Newton tangents of beams numbered along their length (README Sec. 6, R-44): the element
// couples three neighbouring nodes, so kl = ku = 17 whatever the length, and a band LU costs
// about n kl (kl + ku) multiply-adds against n^3/3 dense. Storage as LAPACK's dgbtrf: column c
// holds rows c - ku - kl ... c + kl (the top kl rows take the fill of row interchanges); the
// algorithm is dgbtf2's (unblocked, right-looking, pivot search within the band) with threshold
// partial pivoting: rows are interchanged only when the diagonal is below kPivotThreshold times the
// column's largest entry (UMFPACK's default 0.1; growth per step bounded by 1 + 1/0.1), which keeps
// the beam's rotational columns (diagonal ~ 0.2 of the u-alpha coupling) from pivoting and U within
// ku instead of kl + ku. Storage is sized once; factorize and solve allocate nothing.
#pragma once

#include <vector>

namespace rollspec::rolling {

class BandLU {
 public:
  static constexpr double kPivotThreshold = 0.1;

  BandLU() = default;
  BandLU(int n, int kl, int ku) { resize(n, kl, ku); }
  void resize(int n, int kl, int ku);

  int size() const { return n_; }
  int lower() const { return kl_; }
  int upper() const { return ku_; }
  // Whether (i, j) lies inside the band the matrix may fill.
  bool in_band(int i, int j) const { return i - j <= kl_ && j - i <= ku_; }

  // Entry (i, j) of the matrix before factorize (inside the band only).
  double& at(int i, int j) {
    return ab_[static_cast<std::size_t>(kl_ + ku_ + i - j) + ld_ * static_cast<std::size_t>(j)];
  }
  void set_zero();
  // Pointer p with p[i] = entry (i, j) for the rows i of column j inside the band.
  double* column(int j) {
    return ab_.data() + (ld_ * static_cast<std::size_t>(j) + static_cast<std::size_t>(kl_ + ku_)) - j;
  }

  // In place; false if a pivot is exactly zero (singular) or not finite.
  bool factorize();
  // b <- A^-1 b with the factors.
  void solve(double* b) const;
  // Plain dgbtf2/dgbtrs-style loops over the whole band (no profile skipping), the reference the
  // two above are tested against (the same factors and solutions, bit for bit).
  bool factorize_reference();
  void solve_reference(double* b) const;

 private:
  double* pivot_column(int j, int jp, double big, int km, int& ju);
  double& f(int i, int j) {
    return ab_[static_cast<std::size_t>(kl_ + ku_ + i - j) + ld_ * static_cast<std::size_t>(j)];
  }
  double f(int i, int j) const {
    return ab_[static_cast<std::size_t>(kl_ + ku_ + i - j) + ld_ * static_cast<std::size_t>(j)];
  }
  const double* fp(int i, int j) const {
    return &ab_[static_cast<std::size_t>(kl_ + ku_ + i - j) + ld_ * static_cast<std::size_t>(j)];
  }
  int n_ = 0, kl_ = 0, ku_ = 0;
  std::size_t ld_ = 1;  // 2 kl + ku + 1
  std::vector<double> ab_;
  std::vector<int> piv_;
  std::vector<int> lrows_;  // rows below the diagonal up to the last nonzero of L's column j
  std::vector<int> utop_;   // first row of a nonzero in U's column j
};

}  // namespace rollspec::rolling
