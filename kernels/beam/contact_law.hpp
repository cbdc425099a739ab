#pragma once
// Point contact laws of the ball-on-beam model (kernels/README.md D-10, D-11; seed 001 Eq. 7–8,
// seed 002 Eq. 4, 14), README Eq. (B15)–(B19). The compression delta = w1(xi) + h(xi) - w2 (D-1),
// its rate delta_dot, and, for the linearised law, the blocked force F0(t) come from the caller.
//
//   table              F = P(delta) + c delta_dot          P: monotone cubic table (B14)   (B15)
//   literal_stiffness  F = k_c(delta) delta + c delta_dot  seed 001 Eq. 7 as printed        (B16)
//   hertz              F = (4/3) E* sqrt(R) delta^{3/2} + c delta_dot                       (B17)
//   linearised         F = F0(t) + k0 (delta + d0) + c0 delta_dot   (D-11, seed 002 Eq. 4)  (B18)
//   path               F = P(delta, xi - xi_0) + c delta_dot  P: one rough strip's table (B46)
//
// The third argument of evaluate / in_contact / static_compression is the law's argument `aux`:
// the blocked force F0(t) for the linearised law, the contact position xi (m, physical) for the
// path law, unused otherwise (detail::law_argument in ball_on_beam.hpp supplies it).
//
// Loss of contact (delta <= 0; path: delta <= delta_c(xi) (B45); for the linearised law, F0 + k0 (delta + d0) <= 0):
// the damping term alone (seed 001 Eq. 8) or zero force. The force never pulls: F = max(F, 0) (B19), unless
// `allow_tension` is set for the linearised law (the frequency-domain check needs a linear model).
#include <memory>
#include <vector>

#include "kernels/beam/monotone_table.hpp"
#include "kernels/beam/path_contact_table.hpp"

namespace rollspec::beam {

enum class ContactLawKind { table, literal_stiffness, hertz, linearised, path };
enum class LossOfContact { damping_only, zero_force };
// Which compression rate the damper sees for the nonlinear laws: the material relative velocity
// w1_dot(xi) - w2_dot, or the total d(delta)/dt that also carries the convective terms
// v (w1'(xi) + h'(xi)) (README B20). The linearised law always uses the relative velocity (D-11).
enum class DampingRate { relative_velocity, total };

struct ContactLaw {
  ContactLawKind kind = ContactLawKind::hertz;
  std::vector<double> compression;     // table / literal_stiffness: delta_i, m, increasing
  std::vector<double> values;          // table: P_i, N (nondecreasing); literal: k_c(delta_i), N/m
  double effective_modulus = 115.4e9;  // hertz: E*, Pa
  double radius = 0.02;                // hertz: R, m
  double k0 = 6.8e6;                   // linearised: N/m
  double d0 = 0.0;                     // linearised: m
  double damping = 100.0;              // c_c or c0, N s/m
  LossOfContact loss = LossOfContact::damping_only;
  DampingRate rate = DampingRate::relative_velocity;
  bool allow_tension = false;                    // linearised only
  std::shared_ptr<const PathContactTable> path;  // path: P(delta, xi) of the strip (B41-B45), shared
  double path_origin = 0.0;                      // path: physical xi_0 of the table's position 0 (m)
  double path_start_width = 0.0;  // path: width of the start's slope fit (B46); 0: the first interval's chord
};

struct ContactForce {
  double force;    // N, >= 0 unless tension is allowed
  double d_delta;  // dF/d delta on the active branch
  double d_rate;   // dF/d delta_dot on the active branch
  bool contact;    // false during loss of contact
};

// A contact law made ready for evaluation (tables built once).
class ContactModel {
 public:
  explicit ContactModel(const ContactLaw& law);

  const ContactLaw& law() const { return law_; }
  bool linearised() const { return law_.kind == ContactLawKind::linearised; }

  // F(delta, delta_dot; f0) with f0 the blocked force (linearised law only).
  ContactForce evaluate(double delta, double rate, double f0) const;

  // Contact (not loss of contact) at compression delta: delta > 0, or F0 + k0 (delta + d0) > 0.
  // Path law: the table's force is positive at (delta, xi) (B45, B45b), f0 = xi.
  bool in_contact(double delta, double f0) const {
    if (linearised()) return f0 + law_.k0 * (delta + law_.d0) > 0.0;
    if (path()) return law_.path->touches(delta, f0 - law_.path_origin);
    return delta > 0.0;
  }
  bool path() const { return law_.kind == ContactLawKind::path; }

  // Elastic part only (no damping): P(delta), dP/d delta; zero for delta <= 0. Not for linearised
  // or path (use evaluate).
  void elastic(double delta, double& force, double& stiffness) const;

  // Compression carrying a static load W with no motion: the delta with P(delta) = W (nonlinear
  // laws; path: at xi = f0, B46), or W = f0 + k0 (delta + d0) (linearised). Throws if the load
  // cannot be carried.
  double static_compression(double load, double f0) const;

 private:
  ContactLaw law_;
  MonotoneTable table_;
  double hertz_k_ = 0.0;
};

}  // namespace rollspec::beam
