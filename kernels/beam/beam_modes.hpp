#pragma once
// Euler–Bernoulli beam eigenvalues and eigenfunctions (kernels/README.md D-8; seed 001 Eq. 1, seed 002
// Eq. 5–6). Theory: kernels/beam/README.md Eq. (B1)–(B6).
//
// Clamped–clamped: cos(x) cosh(x) = 1, x = kappa_n l, solved as cos x - sech x = 0 (B1) by a
// safeguarded Newton iteration in the bracket (n + 1/2) pi -/+ pi/4.
//   phi_n(x) = cosh kx - cos kx - sigma_n (sinh kx - sin kx)
// evaluated in the cancellation-free form (B3)
//   phi_n(x) = A e^{k(x-l)} + (1/2)(1+sigma) e^{-kx} - cos kx + sigma sin kx,
//   A = (1/2)(1-sigma) e^{kl} = (cos kl - sin kl - e^{-kl}) / (1 - e^{-2kl} - 2 sin kl e^{-kl}),
// with mirror symmetry phi_n(l-x) = (-1)^{n+1} phi_n(x) so that x <= l/2 always. Nothing
// overflows and nothing cancels for any mode (tested to mode 200).
// Simply supported: kappa_n l = n pi, phi_n = sqrt(2) sin(n pi x / l).
// Both families satisfy int_0^l phi_n^2 dx = l (B4).
namespace rollspec::beam {

enum class Support { clamped_clamped, simply_supported };

// n-th positive root (n = 1, 2, ...) of cos(x) cosh(x) = 1, to full double precision.
double clamped_clamped_root(int n);

// kappa_n l for mode n (1-based).
double wavenumber_length(Support support, int n);

struct ShapeValues {
  double value;      // phi
  double slope;      // d phi / dx, 1/m
  double curvature;  // d2 phi / dx2, 1/m^2
};

// One mode shape on a beam of length l, with the constants of (B3) computed once.
class ModeShape {
 public:
  ModeShape() = default;
  ModeShape(Support support, int n, double length);

  int mode() const { return n_; }
  double kappa() const { return k_; }  // 1/m
  double length() const { return l_; }

  double value(double x) const;          // x in [0, l]
  ShapeValues evaluate(double x) const;  // phi, phi', phi''

 private:
  Support support_ = Support::clamped_clamped;
  int n_ = 0;
  double l_ = 0.0, k_ = 0.0;
  double a_ = 0.0;       // (1/2)(1 - sigma) e^{kl}, (B3)
  double sigma_ = 0.0;   // sigma_n
  double mirror_ = 1.0;  // (-1)^{n+1}
};

}  // namespace rollspec::beam
