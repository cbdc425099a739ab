#pragma once
// A one-sided roughness PSD G(k) as a value the whole texture kernel passes around.
//
//   variance = integral_0^inf G(k) dk,   k in rad/m, G in m^3 (m^2 per rad/m)   (README Eq. 4)
//
// Every model (table, self-affine, ISO 8608, ISO 3095) converts to this type, so the line and
// surface generators and the engine only ever see one thing. `density` may throw
// std::domain_error outside its domain (a table without extension); `support_max` is the
// largest k whose power the model knows (infinity if unbounded) and drives the sampling check
// dx <= pi / k_max of the line and surface generators; the density itself returns 0 where the
// model has no power, the support fields are information, not a mask.
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollspec::texture {

struct Psd {
  std::function<double(double)> density;                         // G(k), m^3, k in rad/m
  double support_min = 0.0;                                      // G = 0 for k < support_min
  double support_max = std::numeric_limits<double>::infinity();  // G = 0 for k > support_max
  std::string description;                                       // for logs and provenance
  std::vector<double> breakpoints;  // k where G or G' jumps (cut-offs, roll-off, table nodes): exact quadrature nodes
  // true: a harmonic j dk carries the PSD's power in its cell, (1/dk) int_{(j-1/2)dk}^{(j+1/2)dk} G dk
  // (Eq. 14b), instead of G(j dk). For tables estimated from profiles, whose power sits in a few
  // steep low bins: the synthesis then keeps the table's variance on any grid (kernels/texture
  // README §5a). Wrappers (band limit, interpolation compensation) keep the flag.
  bool cell_average = false;

  double operator()(double k) const { return density(k); }
};

// A PSD carrying power above what a grid resolves (k_max > pi/dx); k_max lets the caller say how
// fine the grid must be.
struct UnresolvedPsd : std::invalid_argument {
  UnresolvedPsd(const std::string& what, double k) : std::invalid_argument(what), k_max(k) {}
  double k_max;  // rad/m
};

// G with every wavenumber above k_max removed: G(k) = 0 for k > k_max (support_max and a breakpoint
// at k_max). An ideal low-pass of the roughness, used as the anti-alias band limit (beam README B40).
Psd band_limited(Psd psd, double k_max);

// G(k) / sinc^4(k dx / 2), sinc(x) = sin(x)/x: the PSD to synthesise samples at spacing dx from so
// that their piecewise-linear interpolant, whose hat kernel scales a wave of wavenumber k by
// sinc^2(k dx / 2), carries G's power (beam README B40a). Only for a band-limited G, k_max dx < pi
// (the gain at k dx = pi would be 6.1); throws otherwise.
Psd interpolation_compensated(Psd psd, double dx);

// G at the harmonics j dk, j = 0..count-1 (entry 0 is the DC term and set to 0): the density at j dk,
// or with psd.cell_average the cell mean of Eq. 14b (8-point Gauss-Legendre panels split at the
// breakpoints inside the cell). A table without extension throws for a harmonic it does not cover.
std::vector<double> psd_at_harmonics(const Psd& psd, double dk, std::size_t count);

// Trapezoidal integral of k^p G(k) over [k0, k1] on a log-spaced grid with `points` nodes
// (p = 0: variance, p = 2: slope variance). A check, not the exact integrals of the models.
double integrate_psd(const Psd& psd, double k0, double k1, double p = 0.0, std::size_t points = 20001);

}  // namespace rollspec::texture
