#pragma once
// Modal Euler–Bernoulli beam (kernels/README.md D-8, D-9; seed 001 Eq. 1–2, seed 002 Eq. 5–8).
// README Eq. (B9)–(B12).
//
// The modal model spans the effective length l_eff (seed 002 §4.1: clamp rotation is modelled by
// lengthening the beam, by 30 mm there); the physical span [0, l] is centred in it, so a physical
// position x maps to x + (l_eff - l)/2 on the modal beam. All public positions are physical.
//
//   q_n'' + 2 zeta_n omega_n q_n' + omega_n^2 q_n = -phi_n(xi) F_c / (rho A l_eff)     (D-9)
//   omega_n = kappa_n^2 sqrt(EI / rho A),  int phi_n^2 = l_eff
//
// Residual flexibility (static correction, B12): the compliance the truncated modes would add at
// the contact point, R(xi) = G(xi, xi) - sum_{n<=N} phi_n(xi)^2 / (rho A l_eff omega_n^2), with G
// the exact Green's function (B7–B8). On by default.
#include <vector>

#include "kernels/beam/beam_modes.hpp"

namespace rollspec::beam {

struct BeamProperties {
  Support support = Support::clamped_clamped;
  double youngs_modulus = 210e9;  // E, Pa
  double density = 7850.0;        // rho, kg/m^3
  double width = 0.05;            // m (rectangular section)
  double thickness = 0.006;       // m (bending direction)
  double length = 0.4;            // physical span l, m
  double effective_length = 0.0;  // l_eff >= l, m; 0 means l_eff = l
};

// Number of modes: a count, or every mode up to a maximum frequency (one of the two > 0).
struct ModeSelection {
  int count = 0;
  double max_frequency = 0.0;  // Hz
};

// Modal damping ratio zeta_n: from a per-mode table if given (size >= number of modes),
// otherwise zeta_n = loss_factor / 2 (viscous equivalent at resonance, B11).
struct ModalDamping {
  double loss_factor = 0.0;
  std::vector<double> zeta;
};

class ModalBeam {
 public:
  ModalBeam(const BeamProperties& properties, const ModeSelection& selection, const ModalDamping& damping,
            bool static_correction = true);

  const BeamProperties& properties() const { return p_; }
  int modes() const { return static_cast<int>(shape_.size()); }
  double effective_length() const { return l_eff_; }
  double offset() const { return offset_; }              // (l_eff - l) / 2
  double bending_stiffness() const { return ei_; }       // EI, N m^2
  double mass_per_length() const { return rho_a_; }      // rho A, kg/m
  double modal_mass() const { return rho_a_ * l_eff_; }  // rho A l_eff, kg
  double omega(int i) const { return omega_[i]; }        // rad/s, i = 0..modes-1
  double zeta(int i) const { return zeta_[i]; }
  double frequency(int i) const;  // Hz
  const ModeShape& shape(int i) const { return shape_[i]; }
  bool static_correction() const { return static_correction_; }

  // Physical position -> coordinate on the modal beam; throws outside [0, l_eff].
  double modal_coordinate(double x) const;

  // phi_n(x) for all modes (physical x); slope optional (nullptr to skip).
  void shapes(double x, double* phi, double* slope = nullptr) const;

  // Exact static flexibility G(x, a) of the l_eff beam, m/N (B7–B8), physical positions.
  double static_flexibility(double x, double a) const;

  // Residual flexibility at the contact point, m/N (B12); 0 when the correction is off.
  double residual_flexibility(double x) const;

  // Static deflection at x (positive down) under a load P at a from the retained modes only.
  double modal_static_deflection(double x, double a, double load) const;

 private:
  BeamProperties p_;
  double l_eff_, offset_, ei_, rho_a_;
  bool static_correction_;
  std::vector<ModeShape> shape_;
  std::vector<double> omega_, zeta_;
};

}  // namespace rollspec::beam
