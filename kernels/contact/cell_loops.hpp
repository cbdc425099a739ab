#pragma once
// Cell loops shared by the contact solver's displacement- and load-controlled iterations (the
// policies of the Polonsky–Keer core, pk_approach.cpp and pk_force.cpp, and the two references;
// README Eq. 7, 7b): fixed-block reductions with the same bits for any thread count, the CG set
// marks and the preconditioner I + γ L_S. Internal to the kernel.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rollspec::contact::detail {

constexpr unsigned char kOut = 0;   // not in the CG set this iteration
constexpr unsigned char kFree = 1;  // 0 < p < H: CG set (README Eq. 7)

inline double clip(double v, double hardness) { return std::min(std::max(v, 0.0), hardness); }

// The cell loops run over fixed blocks of cells; a block's partial sums are added in block order
// afterwards, so every sum has the same bits for any thread count (one block: the plain loop).
constexpr std::size_t kCellBlock = 8192;
constexpr std::size_t kParallelCells = 2 * kCellBlock;

// γ of the preconditioner I + γ L (README Eq. 7b) for a set of `cells` cells: 0.1 of the radius
// in cells of a disc of half that area (a ball's contact disc is half its interference disc).
inline double precondition_gamma(std::size_t cells) {
  constexpr double two_pi = 6.28318530717958647692;
  return 0.1 * std::sqrt(static_cast<double>(cells) / two_pi);
}

// Entries [lo, hi) of a list of cell indices, for range-for.
struct Slice {
  const std::uint32_t* list;
  std::size_t lo, hi;
  const std::uint32_t* begin() const { return list + lo; }
  const std::uint32_t* end() const { return list + hi; }
};

// f(lo, hi, partial) for each block [lo, hi), in parallel; partial points at the block's K slots
// (zero on entry). Slot k of the result is the sum of the blocks' slots, or their maximum if bit k
// of max_slots is set.
template <std::size_t K, class F>
std::array<double, K> block_reduce(std::size_t n, std::vector<double>& part, F&& f, unsigned max_slots = 0) {
  const std::size_t nb = (n + kCellBlock - 1) / kCellBlock;
  part.assign(nb * K, 0.0);
  const long blocks = static_cast<long>(nb);
#pragma omp parallel for schedule(static) if (n >= kParallelCells)
  for (long b = 0; b < blocks; ++b) {
    const std::size_t lo = static_cast<std::size_t>(b) * kCellBlock;
    f(lo, std::min(n, lo + kCellBlock), part.data() + static_cast<std::size_t>(b) * K);
  }
  std::array<double, K> total{};
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t k = 0; k < K; ++k)
      total[k] = (max_slots >> k) & 1u ? std::max(total[k], part[b * K + k]) : total[k] + part[b * K + k];
  return total;
}

// z = (I + γ L_S) v on the cells of `list` in S (set == kFree), L_S the 5-point Laplacian with
// zero outside S (README Eq. 7b); returns Σ_S v z.
inline double apply_preconditioner(const std::vector<std::uint32_t>& list, const std::vector<unsigned char>& set,
                                   const std::vector<double>& v, std::vector<double>& z, double gamma, std::size_t nx,
                                   std::vector<double>& part) {
  const std::size_t n = set.size();
  return block_reduce<1>(list.size(), part, [&](std::size_t lo, std::size_t hi, double* acc) {
    for (const std::size_t i : Slice{list.data(), lo, hi})
      if (set[i] == kFree) {
        const std::size_t ix = i % nx;
        double nb = 0.0;
        if (ix > 0 && set[i - 1] == kFree) nb += v[i - 1];
        if (ix + 1 < nx && set[i + 1] == kFree) nb += v[i + 1];
        if (i >= nx && set[i - nx] == kFree) nb += v[i - nx];
        if (i + nx < n && set[i + nx] == kFree) nb += v[i + nx];
        z[i] = v[i] + gamma * (4.0 * v[i] - nb);
        acc[0] += v[i] * z[i];
      }
  })[0];
}

}  // namespace rollspec::contact::detail
