#pragma once
// Isotropic 2D PSD C_iso(q) from a one-sided line PSD G(k) (kernels/README.md D-5; README Eq. 18-21).
//
// Jacobs, Junge & Pastewka (2017) normalise h_rms^2 = (2 pi)^-2 int C_iso d^2q and
// h_rms^2 = (1/pi) int_0^inf C_1D dq, so the kernel's one-sided G = C_1D / pi, and D-5 reads
//   C_1D(q) = (1/pi) int_0^inf C_iso(sqrt(q^2 + y^2)) dy                         (Eq. 18, forward)
//   C_iso(r) = -2 pi int_r^inf G'(q) / sqrt(q^2 - r^2) dq                         (Eq. 19, inverse Abel)
//            = -2 pi int_0^inf G'(r cosh t) dt      (q = r cosh t)
// G is represented on a log grid ending at q_e (the PSD's support_max, or a cap if unbounded):
// power law between nodes (linear where a node value is 0), so G' is exact per cell, and the
// drop of G to zero at q_e is a jump J = G(q_e) whose part of Eq. 19 is analytic:
//   C_iso(r) = S(r) + 2 pi J / sqrt(q_e^2 - r^2),   S = the cell integrals (4-point Gauss in t) (Eq. 20)
// The singular term is integrable; a grid mode uses its mean over a radial cell [q - w/2, q + w/2]:
//   2 pi J (asin(min(b, q_e)/q_e) - asin(a/q_e)) / (b - a)                         (Eq. 21)
// The log grid carries the PSD's breakpoints as nodes; S is interpolated log-log between nodes,
// and in sqrt(b - q) in a cell that ends at a breakpoint b (where S has a one-sided sqrt cusp).
// Where G is not the projection of any isotropic field (e.g. a hard long-wavelength cut-off)
// Eq. 19 turns negative; S is clamped at 0 there (the realised 1D PSD then differs below it).
#include <cstddef>
#include <vector>

#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

class IsotropicPsd {
 public:
  // q_min: smallest |q| asked for; q_cap: where an unbounded PSD is truncated.
  IsotropicPsd(const Psd& g, double q_min, double q_cap, std::size_t points_per_decade = 100);

  double operator()(double q) const;                  // Eq. 20, point value (inf at q_e if J > 0)
  double cell_average(double q, double width) const;  // Eq. 20 with the jump term of Eq. 21
  double smooth(double q) const;                      // S(q), log-log between nodes; 0 for q >= q_e
  double q_end() const { return q_.back(); }
  double end_jump() const { return jump_; }
  double clamped_fraction() const { return clamped_; }  // share of nodes where S < 0 was clamped

  // Eq. 18 by composite Simpson in t (q' = q cosh t) on `intervals` intervals, plus the jump's
  // exact share J: the line PSD G this C_iso projects to. The reference check of the Abel pair.
  double forward_line_psd(double q, std::size_t intervals = 4000) const;

 private:
  std::vector<double> q_, g_, s_;
  std::vector<bool> cusp_;  // cell c = [q_c, q_{c+1}] ends at a breakpoint or q_e
  double jump_ = 0.0, clamped_ = 0.0;
  double g_derivative(std::size_t cell, double q) const;
};

}  // namespace rollspec::texture
