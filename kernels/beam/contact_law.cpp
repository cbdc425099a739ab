#include "kernels/beam/contact_law.hpp"

#include "kernels/beam/bracketed_newton.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/contact/hertz.hpp"

namespace rollspec::beam {

ContactModel::ContactModel(const ContactLaw& law) : law_(law) {
  if (!(law.damping >= 0.0)) throw std::invalid_argument("ContactLaw: damping must be >= 0");
  switch (law.kind) {
    case ContactLawKind::table:
    case ContactLawKind::literal_stiffness:
      table_ = MonotoneTable(law.compression, law.values);
      for (std::size_t i = 1; i < law.values.size(); ++i)
        if (law.kind == ContactLawKind::table && law.values[i] < law.values[i - 1])
          throw std::invalid_argument("ContactLaw: force table must be nondecreasing");
      break;
    case ContactLawKind::hertz:
      if (!(law.effective_modulus > 0.0 && law.radius > 0.0))
        throw std::invalid_argument("ContactLaw: Hertz needs E* > 0, R > 0");
      hertz_k_ = contact::hertz::force_coefficient(law.radius, law.effective_modulus);  // (B17)
      break;
    case ContactLawKind::linearised:
      if (!(law.k0 > 0.0)) throw std::invalid_argument("ContactLaw: linearised law needs k0 > 0");
      break;
    case ContactLawKind::path:
      if (!law.path || law.path->empty()) throw std::invalid_argument("ContactLaw: path law needs a path table");
      break;
  }
}

void ContactModel::elastic(double delta, double& force, double& stiffness) const {
  force = stiffness = 0.0;
  if (!(delta > 0.0)) return;
  switch (law_.kind) {
    case ContactLawKind::table:  // (B15)
      table_.evaluate(delta, force, stiffness);
      if (force < 0.0) force = stiffness = 0.0;
      break;
    case ContactLawKind::literal_stiffness: {  // (B16): F = k_c(delta) delta
      double k, dk;
      table_.evaluate(delta, k, dk);
      force = k * delta;
      stiffness = k + dk * delta;
      if (force < 0.0) force = stiffness = 0.0;
      break;
    }
    case ContactLawKind::hertz: {  // (B17)
      const double s = std::sqrt(delta);
      force = hertz_k_ * delta * s;
      stiffness = 1.5 * hertz_k_ * s;
      break;
    }
    case ContactLawKind::linearised:
    case ContactLawKind::path:
      throw std::logic_error("ContactModel::elastic: not defined for the linearised and path laws");
  }
}

ContactForce ContactModel::evaluate(double delta, double rate, double f0) const {
  const double c = law_.damping;
  if (law_.kind == ContactLawKind::linearised) {  // (B18)
    const double spring = f0 + law_.k0 * (delta + law_.d0);
    const bool contact = spring > 0.0;
    double f = spring + c * rate;
    if (law_.allow_tension) return {f, law_.k0, c, contact};
    if (!contact) {  // loss of contact: damping alone (seed 001 Eq. 8) or nothing
      if (law_.loss == LossOfContact::zero_force) return {0.0, 0.0, 0.0, false};
      f = c * rate;
      return f > 0.0 ? ContactForce{f, 0.0, c, false} : ContactForce{0.0, 0.0, 0.0, false};
    }
    if (f <= 0.0) return {0.0, 0.0, 0.0, true};  // (B19) never pulls
    return {f, law_.k0, c, true};
  }
  double p = 0.0, k = 0.0;
  bool contact;
  if (path() && law_.path->data().interpolation == PathInterpolation::cubic) {
    law_.path->evaluate(delta, f0 - law_.path_origin, p, k);  // (B46): contact where the B45b blend is positive
    contact = p > 0.0;
  } else {
    contact = path() ? in_contact(delta, f0) : delta > 0.0;
    if (contact && path())
      law_.path->evaluate(delta, f0 - law_.path_origin, p, k);  // (B46)
    else if (contact)
      elastic(delta, p, k);
  }
  if (!contact) {  // loss of contact: seed 001 Eq. 8, or nothing (path: B46)
    if (law_.loss == LossOfContact::zero_force) return {0.0, 0.0, 0.0, false};
    const double f = c * rate;
    return f > 0.0 ? ContactForce{f, 0.0, c, false} : ContactForce{0.0, 0.0, 0.0, false};
  }
  const double f = p + c * rate;
  if (f <= 0.0) return {0.0, 0.0, 0.0, true};  // (B19)
  return {f, k, c, true};
}

double ContactModel::static_compression(double load, double f0) const {
  if (law_.kind == ContactLawKind::linearised) return (load - f0) / law_.k0 - law_.d0;
  if (path()) return law_.path->static_approach(load, f0 - law_.path_origin);  // (B46, B22)
  if (!(load > 0.0)) return 0.0;
  if (law_.kind == ContactLawKind::hertz) return std::pow(load / hertz_k_, 2.0 / 3.0);
  // Monotone table: bracket then safeguarded Newton.
  double lo = 0.0, hi = table_.x().back() > 0.0 ? table_.x().back() : 1e-6;
  double p, k;
  for (int i = 0; i < 200; ++i) {
    elastic(hi, p, k);
    if (p >= load) break;
    lo = hi;
    hi *= 2.0;
    if (i == 199) throw std::runtime_error("ContactModel: the contact law cannot carry the static load");
  }
  return bracketed_newton(
      lo, hi, load, [this](double x, double& px, double& kx) { elastic(x, px, kx); },
      [](double x, double) { return x; });
}

}  // namespace rollspec::beam
