#include "kernels/contact/half_space_operator.hpp"

#include <cmath>
#include <fftw3.h>

#include <cstring>
#include <stdexcept>

#include "kernels/contact/love_influence.hpp"

namespace rollspec::contact {

HalfSpaceOperator::HalfSpaceOperator(const Grid& grid, double e_star, Boundary boundary, PlannerEffort effort)
    : grid_(grid), e_star_(e_star), boundary_(boundary) {
  check_grid(grid);
  if (!(e_star > 0.0) || !std::isfinite(e_star)) throw std::invalid_argument("HalfSpaceOperator: E* must be > 0");
  const bool open = boundary == Boundary::Open;
  fnx_ = open ? 2 * grid.nx : grid.nx;
  fny_ = open ? 2 * grid.ny : grid.ny;
  ncomplex_ = fny_ * (fnx_ / 2 + 1);
  const std::size_t nreal = fnx_ * fny_;
  in_ = spectral::RealBuffer(nreal);
  out_ = spectral::RealBuffer(nreal);
  spectrum_ = spectral::ComplexBuffer(ncomplex_);
  kernel_ = spectral::ComplexBuffer(ncomplex_);
  const unsigned flags = effort == PlannerEffort::Measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  // Row-major (fny rows of fnx): x is the fastest index, as in Grid.
  const int rows = static_cast<int>(fny_), cols = static_cast<int>(fnx_);
  forward_ = spectral::FftwPlan([&] { return fftw_plan_dft_r2c_2d(rows, cols, in_.data(), spectrum_.data(), flags); },
                                "HalfSpaceOperator forward");
  backward_ = spectral::FftwPlan([&] { return fftw_plan_dft_c2r_2d(rows, cols, spectrum_.data(), out_.data(), flags); },
                                 "HalfSpaceOperator backward");

  const double scale = 1.0 / static_cast<double>(nreal);  // FFTW transforms are unnormalised
  if (open) {
    // Wrap-around coefficients (README Eq. 3): offsets 0..n−1 then −(n−1)..−1; the middle
    // row/column (offset ±n) never multiplies a real cell and is set to zero.
    const long nx = static_cast<long>(grid.nx), ny = static_cast<long>(grid.ny);
    for (long r = 0; r < 2 * ny; ++r) {
      const long oy = r < ny ? r : r - 2 * ny;
      for (long c = 0; c < 2 * nx; ++c) {
        const long ox = c < nx ? c : c - 2 * nx;
        const bool middle = (c == nx) || (r == ny);
        in_[static_cast<std::size_t>(r * 2 * nx + c)] = middle ? 0.0 : love_coefficient(ox, oy, grid.dx, grid.dy, e_star);
      }
    }
    self_ = love_coefficient(0, 0, grid.dx, grid.dy, e_star);
    fftw_execute_dft_r2c(forward_.get(), in_.data(), kernel_.data());
    for (std::size_t k = 0; k < ncomplex_; ++k) {
      kernel_[k][0] *= scale;
      kernel_[k][1] *= scale;
    }
  } else {
    // Spectral Boussinesq symbol 2/(E*|q|) on the DFT frequencies, zero mean mode (README Eq. 4).
    constexpr double two_pi = 6.28318530717958647692;
    const std::size_t nxc = fnx_ / 2 + 1;
    double diag = 0.0;
    for (std::size_t r = 0; r < fny_; ++r) {
      const double my = static_cast<double>(r <= fny_ / 2 ? static_cast<long>(r) : static_cast<long>(r) - static_cast<long>(fny_));
      const double qy = two_pi * my / (static_cast<double>(fny_) * grid.dy);
      for (std::size_t c = 0; c < nxc; ++c) {
        const double qx = two_pi * static_cast<double>(c) / (static_cast<double>(fnx_) * grid.dx);
        const double q = std::sqrt(qx * qx + qy * qy);
        const double symbol = (r == 0 && c == 0) ? 0.0 : 2.0 / (e_star * q);
        kernel_[r * nxc + c][0] = symbol * scale;
        kernel_[r * nxc + c][1] = 0.0;
        // Diagonal = mean of the symbol over the full spectrum (Hermitian half counted twice).
        const bool self_conjugate = (c == 0) || (fnx_ % 2 == 0 && c == fnx_ / 2);
        diag += symbol * (self_conjugate ? 1.0 : 2.0);
      }
    }
    self_ = diag * scale;
  }
  std::memset(in_.data(), 0, sizeof(double) * nreal);
}

void HalfSpaceOperator::apply(const double* p, double* u) {
  const std::size_t nx = grid_.nx, ny = grid_.ny;
  // Only the nx × ny corner of in_ is ever written: the zero padding of DC-FFT persists
  // (out-of-place r2c preserves its input).
  for (std::size_t iy = 0; iy < ny; ++iy) std::memcpy(in_.data() + iy * fnx_, p + iy * nx, sizeof(double) * nx);
  fftw_execute_dft_r2c(forward_.get(), in_.data(), spectrum_.data());
  for (std::size_t k = 0; k < ncomplex_; ++k) {
    const double re = spectrum_[k][0] * kernel_[k][0] - spectrum_[k][1] * kernel_[k][1];
    const double im = spectrum_[k][0] * kernel_[k][1] + spectrum_[k][1] * kernel_[k][0];
    spectrum_[k][0] = re;
    spectrum_[k][1] = im;
  }
  fftw_execute_dft_c2r(backward_.get(), spectrum_.data(), out_.data());
  for (std::size_t iy = 0; iy < ny; ++iy) std::memcpy(u + iy * nx, out_.data() + iy * fnx_, sizeof(double) * nx);
}

}  // namespace rollspec::contact
