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
  lrows_.assign(static_cast<std::size_t>(n), 0);
  utop_.assign(static_cast<std::size_t>(n), 0);
}

void BandLU::set_zero() { std::fill(ab_.begin(), ab_.end(), 0.0); }

namespace {
// y[i] -= x[i] * a, i < n (distinct columns of the band: no overlap)
inline __attribute__((always_inline)) void axpy_minus(double* __restrict y, const double* __restrict x, double a,
                                                      int n) {
  for (int i = 0; i < n; ++i) y[i] -= x[i] * a;
}
}  // namespace

// Column j's step once its pivot row j + jp is chosen (both factorizations): record it, swap the rows
// over the columns the interchanges reach (ju grows), and scale the column below the diagonal by the
// pivot. Returns that column (contiguous), or nullptr for a zero or non-finite pivot.
double* BandLU::pivot_column(int j, int jp, double big, int km, int& ju) {
  piv_[static_cast<std::size_t>(j)] = j + jp;
  if (!(big > 0.0) || !std::isfinite(big)) return nullptr;
  ju = std::max(ju, std::min(j + ku_ + jp, n_ - 1));
  if (jp != 0)
    for (int c = j; c <= ju; ++c) std::swap(f(j, c), f(j + jp, c));
  const double inv = 1.0 / f(j, j);
  double* lj = &f(j + 1 < n_ ? j + 1 : j, j);
  for (int i = 0; i < km; ++i) lj[i] *= inv;
  return lj;
}

bool BandLU::factorize() {
  int ju = 0;  // last column touched by the interchanges so far
  for (int c = 0; c < n_; ++c) utop_[static_cast<std::size_t>(c)] = c;
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    // pivot: the largest |entry| first (an exact max, any order), its first row only when the
    // diagonal falls below the threshold; the same row as a search that keeps the first largest
    const double* cj = &f(j, j);
    double m4[4] = {std::abs(cj[0]), std::abs(cj[0]), std::abs(cj[0]), std::abs(cj[0])};  // 4 chains
    int r = 1;
    for (; r + 3 <= km; r += 4)
      for (int k = 0; k < 4; ++k) m4[k] = std::max(m4[k], std::abs(cj[r + k]));
    for (; r <= km; ++r) m4[0] = std::max(m4[0], std::abs(cj[r]));
    const double big = std::max(std::max(m4[0], m4[1]), std::max(m4[2], m4[3]));
    int jp = 0;
    if (!(std::abs(cj[0]) >= kPivotThreshold * big))  // threshold pivoting
      for (int i = 1; i <= km; ++i)
        if (std::abs(cj[i]) == big) {
          jp = i;
          break;
        }
    double* lj = pivot_column(j, jp, big, km, ju);
    if (lj == nullptr) return false;
    // rows below the last nonzero of the column would only subtract zeros: the update stops
    // there (the profile of the beam's block structure, R-44)
    int kr = km;
    while (kr > 0 && lj[kr - 1] == 0.0) --kr;
    lrows_[static_cast<std::size_t>(j)] = kr;
    // rank-1 update of the band to the right, up to the last nonzero of U's row j (zeros inside
    // the row are updated too: subtracting zero products changes no entry)
    int ce = ju;
    while (ce > j && f(j, ce) == 0.0) --ce;
    for (int c = j + 1; c <= ce; ++c) {
      int& top = utop_[static_cast<std::size_t>(c)];
      if (top > j) top = j;  // first (possibly) nonzero of U's column c
      axpy_minus(&f(j + 1, c), lj, f(j, c), kr);
    }
  }
  return true;
}

void BandLU::solve(double* b) const {
  // the loops skip the entries factorize found zero (subtracting zero products: the same b)
  for (int j = 0; j < n_ - 1; ++j) {  // L y = P b
    const int km = lrows_[static_cast<std::size_t>(j)];
    const int p = piv_[static_cast<std::size_t>(j)];
    if (p != j) std::swap(b[j], b[p]);
    const double bj = b[j];
    axpy_minus(b + j + 1, fp(j + 1 < n_ ? j + 1 : j, j), bj, km);
  }
  for (int j = n_ - 1; j >= 0; --j) {  // U x = y
    b[j] /= f(j, j);
    const double bj = b[j];
    const int top = utop_[static_cast<std::size_t>(j)];
    axpy_minus(b + top, fp(top, j), bj, j - top);
  }
}

void BandLU::solve_reference(double* b) const {
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

bool BandLU::factorize_reference() {
  int ju = 0;
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    int jp = 0;
    double big = std::abs(f(j, j));
    for (int i = 1; i <= km; ++i)
      if (std::abs(f(j + i, j)) > big) {
        big = std::abs(f(j + i, j));
        jp = i;
      }
    if (std::abs(f(j, j)) >= kPivotThreshold * big) jp = 0;
    double* lj = pivot_column(j, jp, big, km, ju);
    if (lj == nullptr) return false;
    for (int c = j + 1; c <= ju; ++c) {
      const double u = f(j, c);
      if (u == 0.0) continue;
      double* col = &f(j + 1, c);
      for (int i = 0; i < km; ++i) col[i] -= lj[i] * u;
    }
  }
  for (int j = 0; j < n_; ++j) {  // solve then runs over the whole band as well
    lrows_[static_cast<std::size_t>(j)] = std::min(kl_, n_ - 1 - j);
    utop_[static_cast<std::size_t>(j)] = std::max(0, j - kl_ - ku_);
  }
  return true;
}

}  // namespace rollspec::rolling
