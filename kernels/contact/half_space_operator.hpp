#pragma once
// Fast product u = C p of the half-space influence matrix with a pressure field (kernels/README.md D-6).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/contact/grid.hpp"
#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::contact {

enum class Boundary {
  // Isolated patch on an infinite half-space: Love coefficients, DC-FFT on a wrap-around grid of
  // at least (2nx − 1) × (2ny − 1) points with zero-padded pressure (Liu, Wang & Liu 2000), README Eq. (3).
  Open,
  // Periodic nx × ny cell (Stanley & Kato 1997): symbol û(q) = 2 p̂(q)/(E*|q|), û(0) = 0,
  // README Eq. (4). The mean displacement of a periodic half-space is undefined, so periodic
  // problems are solved in load control (ContactSolver::solve_load).
  Periodic,
};

enum class PlannerEffort { Estimate, Measure };

// The smallest 2^a 3^b 5^c 7^d ≥ n (n ≥ 1): the padded length of an open-boundary axis is
// fast_fft_length(2n − 1) (README Eq. 3).
std::size_t fast_fft_length(std::size_t n);

// Owns its FFTW plans and aligned buffers: plans are made once (under the one planner lock of
// kernels/spectral/fftw_handles.hpp) and re-executed with the new-array interface on the object's
// own buffers, so distinct objects may be used concurrently from different threads. One object
// must not be used by two threads at once.
//
// The 2-D transform is done as its two 1-D passes (README Eq. 3a): rows, then columns. The rows of
// the zero padding are never transformed forward, and only the nx × ny block is transformed back.
// Each pass runs over fixed blocks of rows / columns, each block with the same FFTW plan whatever
// the thread count, under an OpenMP `parallel for` (one thread inside an enclosing parallel
// region): the product has the same bits for any number of threads.
class HalfSpaceOperator {
 public:
  HalfSpaceOperator(const Grid& grid, double e_star, Boundary boundary = Boundary::Open,
                    PlannerEffort effort = PlannerEffort::Estimate);
  HalfSpaceOperator(const HalfSpaceOperator&) = delete;
  HalfSpaceOperator& operator=(const HalfSpaceOperator&) = delete;

  // u[i] = Σ_k C_ik p[k] for the nx·ny cells (x-fastest arrays). p and u may not alias.
  void apply(const double* p, double* u);

  // The same sum by direct summation (README Eq. 3b), only over the cells `sources` (where p may be
  // non-zero) and only for the cells `targets` (u elsewhere is not written); both lists of cell
  // indices in increasing order. Open boundary only. Each u[t] is one sum in source order: the same
  // bits for any thread count. Worth it while |targets|·|sources| is small against
  // fft_cost() (tiny contact spots on a big grid); the first call tabulates C (4 nx ny doubles).
  void apply_direct(const double* p, const std::vector<std::uint32_t>& sources,
                    const std::vector<std::uint32_t>& targets, double* u);
  // Source–target pairs of apply_direct that cost about one apply().
  double fft_cost() const;

  const Grid& grid() const { return grid_; }
  double e_star() const { return e_star_; }
  Boundary boundary() const { return boundary_; }
  // Diagonal C_ii (displacement of a cell under its own unit pressure).
  double self_coefficient() const { return self_; }
  // Size of the FFT grid (Open: fast_fft_length(2nx − 1) × fast_fft_length(2ny − 1); Periodic: nx × ny).
  std::size_t fft_nx() const { return fnx_; }
  std::size_t fft_ny() const { return fny_; }

 private:
  // One 1-D pass over a block of rows or columns; the plan is made for the first block and re-run
  // on the others (same strides; offsets keep FFTW's alignment, checked at construction).
  struct Pass {
    spectral::FftwPlan full, tail;  // `count` whole blocks of `block` lines, then `rest` lines
    std::size_t block = 0, count = 0, rest = 0;
  };
  void forward_rows(std::size_t r0, std::size_t lines);  // in_ rows → spectrum_ rows
  void columns(std::size_t c0, std::size_t lines, bool multiply);
  void backward_rows(std::size_t r0, std::size_t lines, double* u);
  void transform_kernel();

  Grid grid_;
  double e_star_;
  Boundary boundary_;
  std::size_t fnx_, fny_;
  std::size_t ncx_;          // complex entries of a transformed row, fnx/2 + 1
  std::size_t real_stride_;  // doubles per row of in_/out_ (≥ fnx, a multiple of 8: 64-byte rows)
  std::size_t cplx_stride_;  // complex entries per row of spectrum_/kernel_ (≥ ncx, a multiple of 4)
  double self_ = 0.0;
  spectral::RealBuffer in_;           // ny rows: pressure, zero beyond column nx (the padding stays zero)
  spectral::RealBuffer out_;          // ny rows: displacement
  spectral::ComplexBuffer spectrum_;  // fny rows × cplx_stride
  spectral::ComplexBuffer kernel_;    // transformed coefficients, scaled by 1/(fnx·fny), same layout
  std::vector<double> table_;  // C at offset (ox, oy): index (oy + ny − 1)(2nx − 1) + ox + nx − 1 (apply_direct)
  struct Run {                 // sources next to each other in a row (apply_direct)
    std::int64_t key;          // key of the first: iy (2nx − 1) + ix
    std::uint32_t first;       // its cell index
    std::uint32_t length;
  };
  std::vector<Run> runs_;
  // Plans last: destroyed before the buffers.
  Pass row_r2c_, col_forward_, col_backward_, row_c2r_;
};

}  // namespace rollspec::contact
