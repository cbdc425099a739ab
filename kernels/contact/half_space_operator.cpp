#include "kernels/contact/half_space_operator.hpp"

#include <cmath>
#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "kernels/contact/love_influence.hpp"

namespace rollspec::contact {

namespace {
constexpr std::size_t kRowBlock = 8;     // rows per block of the row passes
constexpr std::size_t kColumnBlock = 8;  // columns per block of the column pass (128 bytes)
// Below this many FFT points (padded 512²) a product takes well under a millisecond: no threads
// (on a busy machine the barriers of a short parallel region cost more than they save).
constexpr std::size_t kParallelPoints = std::size_t(1) << 18;

std::size_t round_up(std::size_t n, std::size_t m) { return (n + m - 1) / m * m; }
std::size_t blocks(std::size_t count, std::size_t rest) { return count + (rest > 0 ? 1 : 0); }
}  // namespace

std::size_t fast_fft_length(std::size_t n) {
  if (n <= 1) return 1;
  for (std::size_t m = n;; ++m) {  // README Eq. 3: the smallest 2^a 3^b 5^c 7^d >= n
    std::size_t r = m;
    for (std::size_t f : {std::size_t(2), std::size_t(3), std::size_t(5), std::size_t(7)})
      while (r % f == 0) r /= f;
    if (r == 1) return m;
  }
}

HalfSpaceOperator::HalfSpaceOperator(const Grid& grid, double e_star, Boundary boundary, PlannerEffort effort)
    : grid_(grid), e_star_(e_star), boundary_(boundary) {
  check_grid(grid);
  if (!(e_star > 0.0) || !std::isfinite(e_star)) throw std::invalid_argument("HalfSpaceOperator: E* must be > 0");
  const bool open = boundary == Boundary::Open;
  // README Eq. 3: the cyclic convolution on L ≥ 2n − 1 points is the aperiodic one exactly; L is
  // the smallest FFT-friendly length (2n itself may hold a large prime: 2·511 = 2·7·73).
  fnx_ = open ? fast_fft_length(2 * grid.nx - 1) : grid.nx;
  fny_ = open ? fast_fft_length(2 * grid.ny - 1) : grid.ny;
  ncx_ = fnx_ / 2 + 1;
  real_stride_ = round_up(fnx_, 8);
  cplx_stride_ = round_up(ncx_, 4);
  const std::size_t ny = grid.ny;
  // in_ holds fny rows while the kernel is transformed (open: the coefficients fill all of them).
  in_ = spectral::RealBuffer(fny_ * real_stride_);
  out_ = spectral::RealBuffer(ny * real_stride_);
  spectrum_ = spectral::ComplexBuffer(fny_ * cplx_stride_);
  kernel_ = spectral::ComplexBuffer(fny_ * cplx_stride_);
  std::memset(static_cast<void*>(spectrum_.data()), 0, sizeof(spectral::FftwComplex) * spectrum_.size());

  const unsigned flags = effort == PlannerEffort::Measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  const int n_row = static_cast<int>(fnx_), n_col = static_cast<int>(fny_);
  const int rs = static_cast<int>(real_stride_), cs = static_cast<int>(cplx_stride_);
  // Plans for a block of `lines` lines starting at row/column `first` (the tail plan is made on
  // the tail's own position, so its alignment is its own).
  auto plan_pass = [&](Pass& pass, std::size_t total, std::size_t block, auto&& make) {
    pass.block = block;
    pass.count = total / block;
    pass.rest = total % block;
    if (pass.count > 0) pass.full = spectral::FftwPlan([&] { return make(0, block); }, "HalfSpaceOperator pass");
    if (pass.rest > 0)
      pass.tail = spectral::FftwPlan([&] { return make(pass.count * block, pass.rest); }, "HalfSpaceOperator pass");
  };
  plan_pass(row_r2c_, ny, kRowBlock, [&](std::size_t r0, std::size_t lines) {
    return fftw_plan_many_dft_r2c(1, &n_row, static_cast<int>(lines), in_.data() + r0 * real_stride_, nullptr, 1, rs,
                                  spectrum_.data() + r0 * cplx_stride_, nullptr, 1, cs, flags);
  });
  for (int sign : {FFTW_FORWARD, FFTW_BACKWARD})
    plan_pass(sign == FFTW_FORWARD ? col_forward_ : col_backward_, ncx_, kColumnBlock,
              [&](std::size_t c0, std::size_t lines) {
                fftw_complex* d = spectrum_.data() + c0;
                return fftw_plan_many_dft(1, &n_col, static_cast<int>(lines), d, nullptr, cs, 1, d, nullptr, cs, 1,
                                          sign, flags);
              });
  plan_pass(row_c2r_, ny, kRowBlock, [&](std::size_t r0, std::size_t lines) {
    return fftw_plan_many_dft_c2r(1, &n_row, static_cast<int>(lines), spectrum_.data() + r0 * cplx_stride_, nullptr, 1,
                                  cs, out_.data() + r0 * real_stride_, nullptr, 1, rs, flags);
  });
  // Every block re-runs its pass's plan: its arrays must have the plan's alignment. The strides
  // (64-byte rows, 128-byte column blocks) make it so; checked here, not assumed.
  for (std::size_t r0 = 0; r0 < fny_; r0 += kRowBlock)
    if (fftw_alignment_of(in_.data() + r0 * real_stride_) != fftw_alignment_of(in_.data()) ||
        fftw_alignment_of(reinterpret_cast<double*>(spectrum_.data() + r0 * cplx_stride_)) !=
            fftw_alignment_of(reinterpret_cast<double*>(spectrum_.data())))
      throw std::logic_error("HalfSpaceOperator: row blocks lost FFTW's alignment");

  const double scale = 1.0 / static_cast<double>(fnx_ * fny_);  // FFTW transforms are unnormalised
  if (open) {
    // Wrap-around coefficients (README Eq. 3): offsets 0..n−1 at the start, −(n−1)..−1 at the end of
    // each padded axis; the points between (offsets ±n … , never met by a pair of real cells) are zero.
    const long nx = static_cast<long>(grid.nx), nyl = static_cast<long>(ny);
    const long fnx = static_cast<long>(fnx_), fny = static_cast<long>(fny_);
    for (long r = 0; r < fny; ++r) {
      const long oy = r < nyl ? r : r - fny;
      for (long c = 0; c < fnx; ++c) {
        const long ox = c < nx ? c : c - fnx;
        const bool middle = (c >= nx && c <= fnx - nx) || (r >= nyl && r <= fny - nyl);
        in_[static_cast<std::size_t>(r) * real_stride_ + static_cast<std::size_t>(c)] =
            middle ? 0.0 : love_coefficient(ox, oy, grid.dx, grid.dy, e_star);
      }
    }
    self_ = love_coefficient(0, 0, grid.dx, grid.dy, e_star);
    transform_kernel();
    for (std::size_t k = 0; k < kernel_.size(); ++k) {
      kernel_[k][0] = spectrum_[k][0] * scale;
      kernel_[k][1] = spectrum_[k][1] * scale;
    }
  } else {
    // Spectral Boussinesq symbol 2/(E*|q|) on the DFT frequencies, zero mean mode (README Eq. 4).
    constexpr double two_pi = 6.28318530717958647692;
    double diag = 0.0;
    std::memset(static_cast<void*>(kernel_.data()), 0, sizeof(spectral::FftwComplex) * kernel_.size());
    for (std::size_t r = 0; r < fny_; ++r) {
      const double my =
          static_cast<double>(r <= fny_ / 2 ? static_cast<long>(r) : static_cast<long>(r) - static_cast<long>(fny_));
      const double qy = two_pi * my / (static_cast<double>(fny_) * grid.dy);
      for (std::size_t c = 0; c < ncx_; ++c) {
        const double qx = two_pi * static_cast<double>(c) / (static_cast<double>(fnx_) * grid.dx);
        const double q = std::sqrt(qx * qx + qy * qy);
        const double symbol = (r == 0 && c == 0) ? 0.0 : 2.0 / (e_star * q);
        kernel_[r * cplx_stride_ + c][0] = symbol * scale;
        // Diagonal = mean of the symbol over the full spectrum (Hermitian half counted twice).
        const bool self_conjugate = (c == 0) || (fnx_ % 2 == 0 && c == fnx_ / 2);
        diag += symbol * (self_conjugate ? 1.0 : 2.0);
      }
    }
    self_ = diag * scale;
  }
  std::memset(in_.data(), 0, sizeof(double) * in_.size());
  std::memset(static_cast<void*>(spectrum_.data()), 0, sizeof(spectral::FftwComplex) * spectrum_.size());
}

// Forward transform of all fny rows of in_ (the coefficients), rows then columns, into spectrum_.
// The row plans cover ny rows; the fny rows are run as whole blocks of kRowBlock rows, the last block
// overlapping the one before it if fny is not a multiple (out of place: re-transforming a row is harmless).
void HalfSpaceOperator::transform_kernel() {
  if (row_r2c_.count == 0) {  // fewer than kRowBlock rows: one plan for all fny rows, made here once
    const int n_row = static_cast<int>(fnx_);
    spectral::FftwPlan all(
        [&] {
          return fftw_plan_many_dft_r2c(1, &n_row, static_cast<int>(fny_), in_.data(), nullptr, 1,
                                        static_cast<int>(real_stride_), spectrum_.data(), nullptr, 1,
                                        static_cast<int>(cplx_stride_), FFTW_ESTIMATE);
        },
        "HalfSpaceOperator kernel rows");
    fftw_execute_dft_r2c(all.get(), in_.data(), spectrum_.data());
  } else {
    for (std::size_t r = 0; r < fny_; r += kRowBlock) {
      const std::size_t r0 = std::min(r, fny_ - kRowBlock);
      fftw_execute_dft_r2c(row_r2c_.full.get(), in_.data() + r0 * real_stride_, spectrum_.data() + r0 * cplx_stride_);
    }
  }
  for (std::size_t k = 0; k < blocks(col_forward_.count, col_forward_.rest); ++k) {
    fftw_complex* d = spectrum_.data() + k * kColumnBlock;
    fftw_execute_dft(k < col_forward_.count ? col_forward_.full.get() : col_forward_.tail.get(), d, d);
  }
}

void HalfSpaceOperator::forward_rows(std::size_t r0, std::size_t lines) {
  fftw_execute_dft_r2c(lines == kRowBlock ? row_r2c_.full.get() : row_r2c_.tail.get(), in_.data() + r0 * real_stride_,
                       spectrum_.data() + r0 * cplx_stride_);
  // Rows of the zero padding: their transform is zero (the column pass reads and overwrites them).
  // Block [r0, r0 + lines) of the ny rows clears its share of the fny − ny padding rows.
  const std::size_t ny = grid_.ny, pad = fny_ - ny;
  const std::size_t p0 = ny + r0 * pad / ny, p1 = ny + (r0 + lines) * pad / ny;
  if (p1 > p0)
    std::memset(static_cast<void*>(spectrum_.data() + p0 * cplx_stride_), 0,
                sizeof(spectral::FftwComplex) * (p1 - p0) * cplx_stride_);
}

void HalfSpaceOperator::columns(std::size_t c0, std::size_t lines, bool multiply) {
  fftw_complex* d = spectrum_.data() + c0;
  const bool full = lines == kColumnBlock;
  fftw_execute_dft(full ? col_forward_.full.get() : col_forward_.tail.get(), d, d);
  if (multiply) {
    for (std::size_t r = 0; r < fny_; ++r) {
      fftw_complex* s = d + r * cplx_stride_;
      const spectral::FftwComplex* k = kernel_.data() + r * cplx_stride_ + c0;
      for (std::size_t j = 0; j < lines; ++j) {
        const double re = s[j][0] * k[j][0] - s[j][1] * k[j][1];
        const double im = s[j][0] * k[j][1] + s[j][1] * k[j][0];
        s[j][0] = re;
        s[j][1] = im;
      }
    }
  }
  fftw_execute_dft(full ? col_backward_.full.get() : col_backward_.tail.get(), d, d);
}

void HalfSpaceOperator::backward_rows(std::size_t r0, std::size_t lines, double* u) {
  fftw_execute_dft_c2r(lines == kRowBlock ? row_c2r_.full.get() : row_c2r_.tail.get(),
                       spectrum_.data() + r0 * cplx_stride_, out_.data() + r0 * real_stride_);
  const std::size_t nx = grid_.nx;
  for (std::size_t iy = r0; iy < r0 + lines; ++iy)
    std::memcpy(u + iy * nx, out_.data() + iy * real_stride_, sizeof(double) * nx);
}

double HalfSpaceOperator::fft_cost() const {
  // Measured (Release, one thread, 128² to 512²): a padded product ≈ 0.33–0.4 ns · N log2 N
  // (N = fnx fny points); a pair of the direct sum 0.31–0.33 ns in long runs of sources (compact
  // spots), more in short ones (scattered micro-contacts).
  const double points = static_cast<double>(fnx_ * fny_);
  return 0.7 * points * std::log2(points);
}

void HalfSpaceOperator::apply_direct(const double* p, const std::vector<std::uint32_t>& sources,
                                     const std::vector<std::uint32_t>& targets, double* u) {
  if (boundary_ != Boundary::Open) throw std::logic_error("HalfSpaceOperator::apply_direct: open boundary only");
  const std::size_t nx = grid_.nx, ny = grid_.ny, width = 2 * nx - 1;
  if (table_.empty()) {
    table_.resize(width * (2 * ny - 1));
    for (std::size_t r = 0; r < 2 * ny - 1; ++r)
      for (std::size_t c = 0; c < width; ++c)
        table_[r * width + c] =
            love_coefficient(static_cast<long>(c) - static_cast<long>(nx - 1),
                             static_cast<long>(r) - static_cast<long>(ny - 1), grid_.dx, grid_.dy, e_star_);
  }
  // README Eq. 3b: with key(i) = iy (2nx − 1) + ix and C even in both offsets,
  // C_ts = table[centre − key(t) + key(s)], centre = (ny − 1)(2nx − 1) + nx − 1. Sources that are
  // neighbours in a row are neighbours in the table too: the sum runs over such runs as dot products.
  runs_.clear();
  for (std::size_t j = 0; j < sources.size(); ++j) {
    const std::uint32_t i = sources[j];
    const bool extends = j > 0 && i == sources[j - 1] + 1 && i % nx != 0;
    if (extends) {
      ++runs_.back().length;
    } else {
      runs_.push_back(Run{static_cast<std::int64_t>((i / nx) * width + i % nx), i, 1});
    }
  }
  const std::int64_t centre = static_cast<std::int64_t>((ny - 1) * width + nx - 1);
  const long count = static_cast<long>(targets.size());
  const double* table = table_.data();
  const Run* runs = runs_.data();
  const std::size_t nruns = runs_.size();
#pragma omp parallel for schedule( \
    static) if (static_cast <double>(targets.size()) * static_cast <double>(sources.size()) > 2e6)
  for (long k = 0; k < count; ++k) {
    const std::uint32_t t = targets[static_cast<std::size_t>(k)];
    const double* row = table + (centre - static_cast<std::int64_t>((t / nx) * width + t % nx));
    // Four partial sums in a fixed pattern: the same bits every time.
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (std::size_t q = 0; q < nruns; ++q) {
      const double* c = row + runs[q].key;
      const double* v = p + runs[q].first;
      const std::size_t len = runs[q].length;
      std::size_t j = 0;
      for (; j + 4 <= len; j += 4) {
        s0 += c[j] * v[j];
        s1 += c[j + 1] * v[j + 1];
        s2 += c[j + 2] * v[j + 2];
        s3 += c[j + 3] * v[j + 3];
      }
      for (; j < len; ++j) s0 += c[j] * v[j];
    }
    u[t] = (s0 + s1) + (s2 + s3);
  }
}

void HalfSpaceOperator::apply(const double* p, double* u) {
  const std::size_t nx = grid_.nx, ny = grid_.ny;
  const long row_blocks = static_cast<long>(blocks(row_r2c_.count, row_r2c_.rest));
  const long col_blocks = static_cast<long>(blocks(col_forward_.count, col_forward_.rest));
  // README Eq. 3a: rows of the pressure (only the ny rows that are not padding), the columns
  // (forward, times the kernel's transform, back), then only the ny rows of u that are wanted.
#pragma omp parallel if (fnx_ * fny_ >= kParallelPoints)
  {
#pragma omp for schedule(static)
    for (long k = 0; k < row_blocks; ++k) {
      const std::size_t r0 = static_cast<std::size_t>(k) * kRowBlock, lines = std::min(kRowBlock, ny - r0);
      // Only the nx columns of in_ are written: the padding beyond stays zero (r2c keeps its input).
      for (std::size_t iy = r0; iy < r0 + lines; ++iy)
        std::memcpy(in_.data() + iy * real_stride_, p + iy * nx, sizeof(double) * nx);
      forward_rows(r0, lines);
    }
#pragma omp for schedule(static)
    for (long k = 0; k < col_blocks; ++k) {
      const std::size_t c0 = static_cast<std::size_t>(k) * kColumnBlock;
      columns(c0, std::min(kColumnBlock, ncx_ - c0), true);
    }
#pragma omp for schedule(static)
    for (long k = 0; k < row_blocks; ++k) {
      const std::size_t r0 = static_cast<std::size_t>(k) * kRowBlock;
      backward_rows(r0, std::min(kRowBlock, ny - r0), u);
    }
  }
}

}  // namespace rollspec::contact
