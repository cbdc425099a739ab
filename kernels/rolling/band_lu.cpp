#include "kernels/rolling/band_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rollspec::rolling {

void BandLU::resize(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  ld_ = static_cast<std::size_t>(2 * kl + ku + 1);
  ab_.assign(ld_ * static_cast<std::size_t>(n), 0.0);
  piv_.assign(static_cast<std::size_t>(n), 0);
}

void BandLU::set_zero() { std::fill(ab_.begin(), ab_.end(), 0.0); }

bool BandLU::factorize() {
  int ju = 0;                // last column touched by the interchanges so far
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    int jp = 0;
    double big = std::abs(f(j, j));
    for (int i = 1; i <= km; ++i)
      if (std::abs(f(j + i, j)) > big) {
        big = std::abs(f(j + i, j));
        jp = i;
      }
    if (std::abs(f(j, j)) >= kPivotThreshold * big) jp = 0;  // threshold pivoting
    piv_[static_cast<std::size_t>(j)] = j + jp;
    if (!(big > 0.0) || !std::isfinite(big)) return false;
    ju = std::max(ju, std::min(j + ku_ + jp, n_ - 1));
    if (jp != 0)
      for (int c = j; c <= ju; ++c) std::swap(f(j, c), f(j + jp, c));
    const double inv = 1.0 / f(j, j);
    double* lj = &f(j + 1 < n_ ? j + 1 : j, j);  // column j below the diagonal, contiguous
    for (int i = 0; i < km; ++i) lj[i] *= inv;
    for (int c = j + 1; c <= ju; ++c) {  // rank-1 update of the band to the right
      const double u = f(j, c);
      if (u == 0.0) continue;
      double* col = &f(j + 1, c);
      for (int i = 0; i < km; ++i) col[i] -= lj[i] * u;
    }
  }
  return true;
}

void BandLU::solve(double* b) const {
  const int kv = kl_ + ku_;
  for (int j = 0; j < n_ - 1; ++j) {  // L y = P b
    const int km = std::min(kl_, n_ - 1 - j);
    const int p = piv_[static_cast<std::size_t>(j)];
    if (p != j) std::swap(b[j], b[p]);
    const double bj = b[j];
    for (int i = 1; i <= km; ++i) b[j + i] -= f(j + i, j) * bj;
  }
  for (int j = n_ - 1; j >= 0; --j) {  // U x = y
    b[j] /= f(j, j);
    const double bj = b[j];
    for (int i = std::max(0, j - kv); i < j; ++i) b[i] -= f(i, j) * bj;
  }
}

}  // namespace rollspec::rolling
