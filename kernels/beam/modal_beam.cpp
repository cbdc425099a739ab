#include "kernels/beam/modal_beam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/beam/static_flexibility.hpp"

namespace rollspec::beam {

namespace {
constexpr double two_pi = 6.28318530717958647692;
}

ModalBeam::ModalBeam(const BeamProperties& p, const ModeSelection& sel, const ModalDamping& damping,
                     bool static_correction)
    : p_(p), static_correction_(static_correction) {
  if (!(p.youngs_modulus > 0.0 && p.density > 0.0 && p.width > 0.0 && p.thickness > 0.0 && p.length > 0.0))
    throw std::invalid_argument("ModalBeam: E, rho, width, thickness and length must be > 0");
  l_eff_ = p.effective_length > 0.0 ? p.effective_length : p.length;
  if (l_eff_ < p.length) throw std::invalid_argument("ModalBeam: effective length shorter than the span");
  offset_ = 0.5 * (l_eff_ - p.length);
  ei_ = p.youngs_modulus * p.width * p.thickness * p.thickness * p.thickness / 12.0;
  rho_a_ = p.density * p.width * p.thickness;
  const double c = std::sqrt(ei_ / rho_a_);
  if (sel.count <= 0 && !(sel.max_frequency > 0.0))
    throw std::invalid_argument("ModalBeam: give a mode count or a maximum frequency");
  for (int n = 1;; ++n) {
    if (sel.count > 0 && n > sel.count) break;
    const double kl = wavenumber_length(p.support, n);
    const double w = kl * kl / (l_eff_ * l_eff_) * c;  // omega_n = kappa_n^2 sqrt(EI/rho A) (D-9)
    if (sel.count <= 0 && w / two_pi > sel.max_frequency) break;
    shape_.emplace_back(p.support, n, l_eff_);
    omega_.push_back(w);
  }
  if (shape_.empty()) throw std::invalid_argument("ModalBeam: no mode below the maximum frequency");
  if (!damping.zeta.empty()) {
    if (damping.zeta.size() < shape_.size())
      throw std::invalid_argument("ModalBeam: damping table shorter than the mode count");
    zeta_.assign(damping.zeta.begin(), damping.zeta.begin() + static_cast<long>(shape_.size()));
  } else {
    zeta_.assign(shape_.size(), 0.5 * damping.loss_factor);  // (B11)
  }
  for (double z : zeta_)
    if (!(z >= 0.0)) throw std::invalid_argument("ModalBeam: damping must be >= 0");
}

double ModalBeam::frequency(int i) const { return omega_[i] / two_pi; }

double ModalBeam::modal_coordinate(double x) const {
  const double y = x + offset_;
  if (!(y >= -1e-12 * l_eff_ && y <= l_eff_ * (1.0 + 1e-12)))
    throw std::out_of_range("ModalBeam: position outside the beam");
  return std::min(std::max(y, 0.0), l_eff_);
}

void ModalBeam::shapes(double x, double* phi, double* slope) const {
  const double y = modal_coordinate(x);
  for (int i = 0; i < modes(); ++i) {
    const ShapeValues s = shape_[i].evaluate(y);
    phi[i] = s.value;
    if (slope) slope[i] = s.slope;
  }
}

double ModalBeam::static_flexibility(double x, double a) const {
  return rollspec::beam::static_flexibility(p_.support, l_eff_, ei_, modal_coordinate(x), modal_coordinate(a));
}

double ModalBeam::modal_static_deflection(double x, double a, double load) const {
  const double yx = modal_coordinate(x), ya = modal_coordinate(a);
  double w = 0.0;
  for (int i = 0; i < modes(); ++i)
    w += shape_[i].value(yx) * shape_[i].value(ya) / (modal_mass() * omega_[i] * omega_[i]);
  return w * load;
}

double ModalBeam::residual_flexibility(double x) const {
  if (!static_correction_) return 0.0;
  // (B12); the difference is positive (every retained term is a positive part of G).
  return static_flexibility(x, x) - modal_static_deflection(x, x, 1.0);
}

}  // namespace rollspec::beam
