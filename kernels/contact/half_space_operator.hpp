#pragma once
// Fast product u = C p of the half-space influence matrix with a pressure field (design.md D-6).
#include <cstddef>

#include "kernels/contact/grid.hpp"
#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::contact {

enum class Boundary {
  // Isolated patch on an infinite half-space: Love coefficients, DC-FFT on a 2nx × 2ny
  // wrap-around grid with zero-padded pressure (Liu, Wang & Liu 2000), README Eq. (3).
  Open,
  // Periodic nx × ny cell (Stanley & Kato 1997): symbol û(q) = 2 p̂(q)/(E*|q|), û(0) = 0,
  // README Eq. (4). The mean displacement of a periodic half-space is undefined, so periodic
  // problems are solved in load control (ContactSolver::solve_load).
  Periodic,
};

enum class PlannerEffort { Estimate, Measure };

// Owns its FFTW plans and aligned buffers: plans are made once (under the one planner lock of
// kernels/spectral/fftw_handles.hpp) and re-executed with fftw_execute_dft_r2c/c2r on the object's own
// buffers, so distinct objects may be used concurrently from different threads. One object must not
// be used by two threads at once.
class HalfSpaceOperator {
 public:
  HalfSpaceOperator(const Grid& grid, double e_star, Boundary boundary = Boundary::Open,
                    PlannerEffort effort = PlannerEffort::Estimate);
  HalfSpaceOperator(const HalfSpaceOperator&) = delete;
  HalfSpaceOperator& operator=(const HalfSpaceOperator&) = delete;

  // u[i] = Σ_k C_ik p[k] for the nx·ny cells (x-fastest arrays). p and u may not alias.
  void apply(const double* p, double* u);

  const Grid& grid() const { return grid_; }
  double e_star() const { return e_star_; }
  Boundary boundary() const { return boundary_; }
  // Diagonal C_ii (displacement of a cell under its own unit pressure).
  double self_coefficient() const { return self_; }
  // Size of the FFT grid (2nx × 2ny for Open, nx × ny for Periodic).
  std::size_t fft_nx() const { return fnx_; }
  std::size_t fft_ny() const { return fny_; }

 private:
  Grid grid_;
  double e_star_;
  Boundary boundary_;
  std::size_t fnx_, fny_, ncomplex_;
  double self_ = 0.0;
  spectral::RealBuffer in_;         // padded pressure (padding stays zero)
  spectral::RealBuffer out_;        // padded displacement
  spectral::ComplexBuffer spectrum_;
  spectral::ComplexBuffer kernel_;  // transformed coefficients, scaled by 1/(fnx·fny)
  spectral::FftwPlan forward_, backward_;  // declared after the buffers: destroyed before them
};

}  // namespace rollspec::contact
